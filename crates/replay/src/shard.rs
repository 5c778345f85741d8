//! Shards and their merge, shared by every batch command (`tournament`, `breaks`, `soak`,
//! `study`).
//!
//! A batch command is a pure function of its arguments to a JSON result. Its work is a list
//! of items numbered from 0 (games, breaks, scenes, grid cells), each drawing its random
//! numbers from the command's seed and its own number only. `--shard K/M` does the items
//! `i` with `i % M == K - 1` and writes them with `"shard": {"k": K, "m": M}`; `--merge`
//! reads the M files back and, only if they are exactly the M shards of one run, writes what
//! a single process would have written: the same JSON, bit for bit (timing fields aside).
//!
//! [`merge`] refuses, with a [`MergeError`] that names the file: a file it cannot read; a
//! truncated file; one that is not JSON or not a result of this command; a whole run (no
//! shard); another run (other arguments or another shard count); a shard given twice; a
//! shard whose items are not all there (or are not its own); and a missing shard.

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};

/// Slice `k` of `m` (1 <= k <= m): the items `i` with `i % m == k - 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// Which slice, from 1.
    pub k: u64,
    /// How many slices.
    pub m: u64,
}

impl Shard {
    /// The whole run: slice 1 of 1.
    pub const WHOLE: Shard = Shard { k: 1, m: 1 };

    /// Whether item `i` is in this slice.
    pub fn contains(self, i: u64) -> bool {
        i % self.m == self.k - 1
    }

    /// How many of the items `0..n` are in this slice.
    pub fn count(self, n: u64) -> u64 {
        let first = self.k - 1;
        if n <= first {
            0
        } else {
            (n - first).div_ceil(self.m)
        }
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.k, self.m)
    }
}

/// Parses `K/M` with 1 <= K <= M (the value of `--shard`).
pub fn parse_shard(s: &str) -> Result<Shard, String> {
    let bad = || format!("{s:?}: expected K/M with 1 <= K <= M");
    let (k, m) = s.split_once('/').ok_or_else(bad)?;
    let (k, m): (u64, u64) = (
        k.trim().parse().map_err(|_| bad())?,
        m.trim().parse().map_err(|_| bad())?,
    );
    if k == 0 || m == 0 || k > m {
        return Err(bad());
    }
    Ok(Shard { k, m })
}

/// What the merge needs of a batch command's result.
pub trait Batch: Serialize + DeserializeOwned {
    /// The command's name, as written in the result's `"command"` field.
    const COMMAND: &'static str;

    /// The shard this result holds (`None`: a whole run).
    fn shard(&self) -> Option<Shard>;

    /// Sets the shard (the merge sets `None`).
    fn set_shard(&mut self, shard: Option<Shard>);

    /// Everything that determines the result besides the shard: two shards of one run have
    /// equal arguments.
    fn arguments(&self) -> serde_json::Value;

    /// `Ok` when the result holds exactly the items of its shard; otherwise what is wrong.
    fn check_items(&self) -> Result<(), String>;

    /// Takes in another shard's items.
    fn absorb(&mut self, other: Self);

    /// Puts the items in the order a whole run writes them.
    fn finish(&mut self);
}

/// Why shard files were not merged.
#[derive(Debug, thiserror::Error)]
pub enum MergeError {
    /// `--merge` without files.
    #[error("--merge: no files given")]
    NoFiles,
    /// A file could not be read.
    #[error("{path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A file ends before its JSON does: cut short while it was written or copied.
    #[error("{path}: truncated: the JSON ends early ({detail})")]
    Truncated {
        /// The file.
        path: PathBuf,
        /// Where the parser stopped.
        detail: String,
    },
    /// A file is not JSON, or not a result of this command in this format.
    #[error("{path}: not a result of `{command}`: {detail}")]
    NotAResult {
        /// The file.
        path: PathBuf,
        /// The command merging.
        command: &'static str,
        /// Why.
        detail: String,
    },
    /// A file holds the result of another command.
    #[error("{path}: a result of `{found}`, not of `{command}`")]
    OtherCommand {
        /// The file.
        path: PathBuf,
        /// The command merging.
        command: &'static str,
        /// The file's command.
        found: String,
    },
    /// A file holds a whole run, not a shard.
    #[error("{path}: a whole run, not a shard (written without --shard, or already merged)")]
    NotAShard {
        /// The file.
        path: PathBuf,
    },
    /// A file is a shard of another run: other arguments.
    #[error("{path}: another run than {first}: its arguments differ ({detail})")]
    OtherArguments {
        /// The file.
        path: PathBuf,
        /// The first file, the reference.
        first: PathBuf,
        /// The arguments that differ.
        detail: String,
    },
    /// A file is a shard of a run split another way.
    #[error("{path}: shard {shard}, but {first} is one of {m}: another split of the seeds")]
    OtherSplit {
        /// The file.
        path: PathBuf,
        /// Its shard.
        shard: Shard,
        /// The first file.
        first: PathBuf,
        /// The first file's shard count.
        m: u64,
    },
    /// Two files hold the same shard: their items overlap.
    #[error("{path}: shard {shard} is also {other}: the seeds overlap")]
    Overlap {
        /// The file.
        path: PathBuf,
        /// The shard.
        shard: Shard,
        /// The other file with it.
        other: PathBuf,
    },
    /// A file does not hold exactly its shard's items.
    #[error("{path}: shard {shard} is incomplete or altered: {detail}")]
    Items {
        /// The file.
        path: PathBuf,
        /// Its shard.
        shard: Shard,
        /// What is wrong.
        detail: String,
    },
    /// Shards are missing.
    #[error("shards missing (of {m}): {missing}: their seeds were not run")]
    Missing {
        /// The missing shards' numbers, `K, K, ...`.
        missing: String,
        /// The shard count.
        m: u64,
    },
}

/// Reads one result file of `T`.
fn read<T: Batch>(path: &Path) -> Result<T, MergeError> {
    let text = std::fs::read_to_string(path).map_err(|source| MergeError::Read {
        path: path.into(),
        source,
    })?;
    let value: serde_json::Value = serde_json::from_str(&text).map_err(|e| {
        if e.is_eof() {
            MergeError::Truncated {
                path: path.into(),
                detail: e.to_string(),
            }
        } else {
            MergeError::NotAResult {
                path: path.into(),
                command: T::COMMAND,
                detail: format!("not JSON: {e}"),
            }
        }
    })?;
    match value.get("command").and_then(|c| c.as_str()) {
        // Tournament results written before shards were checked carry no command.
        None if T::COMMAND == "tournament" => {}
        None => {
            return Err(MergeError::NotAResult {
                path: path.into(),
                command: T::COMMAND,
                detail: "no \"command\" field".into(),
            });
        }
        Some(c) if c != T::COMMAND => {
            return Err(MergeError::OtherCommand {
                path: path.into(),
                command: T::COMMAND,
                found: c.into(),
            });
        }
        Some(_) => {}
    }
    serde_json::from_value(value).map_err(|e| MergeError::NotAResult {
        path: path.into(),
        command: T::COMMAND,
        detail: e.to_string(),
    })
}

/// The top-level fields in which two argument objects differ, by name.
fn differences(a: &serde_json::Value, b: &serde_json::Value) -> String {
    match (a.as_object(), b.as_object()) {
        (Some(a), Some(b)) => {
            let mut keys: Vec<&String> = a.keys().chain(b.keys()).collect();
            keys.sort();
            keys.dedup();
            keys.into_iter()
                .filter(|k| a.get(*k) != b.get(*k))
                .map(|k| {
                    let show = |v: Option<&serde_json::Value>| {
                        v.map_or("absent".to_string(), |v| v.to_string())
                    };
                    format!("{k}: {} against {}", show(b.get(k)), show(a.get(k)))
                })
                .collect::<Vec<_>>()
                .join("; ")
        }
        _ => "not objects".into(),
    }
}

/// The shard files `files` (in any order) as the result of one whole run, or why not.
pub fn merge<T: Batch>(files: &[PathBuf]) -> Result<T, MergeError> {
    let mut shards: Vec<(PathBuf, T)> = Vec::with_capacity(files.len());
    for path in files {
        let r: T = read(path)?;
        let Some(shard) = r.shard() else {
            return Err(MergeError::NotAShard { path: path.clone() });
        };
        if let Some((first, f)) = shards.first() {
            let (a, b) = (f.arguments(), r.arguments());
            if a != b {
                return Err(MergeError::OtherArguments {
                    path: path.clone(),
                    first: first.clone(),
                    detail: differences(&a, &b),
                });
            }
            let m = f.shard().map_or(1, |s| s.m);
            if shard.m != m {
                return Err(MergeError::OtherSplit {
                    path: path.clone(),
                    shard,
                    first: first.clone(),
                    m,
                });
            }
        }
        if let Some((other, _)) = shards.iter().find(|(_, s)| s.shard() == Some(shard)) {
            return Err(MergeError::Overlap {
                path: path.clone(),
                shard,
                other: other.clone(),
            });
        }
        r.check_items().map_err(|detail| MergeError::Items {
            path: path.clone(),
            shard,
            detail,
        })?;
        shards.push((path.clone(), r));
    }
    let m = shards
        .first()
        .and_then(|(_, s)| s.shard())
        .ok_or(MergeError::NoFiles)?
        .m;
    let missing: Vec<String> = (1..=m)
        .filter(|k| {
            !shards
                .iter()
                .any(|(_, s)| s.shard().is_some_and(|x| x.k == *k))
        })
        .map(|k| k.to_string())
        .collect();
    if !missing.is_empty() {
        return Err(MergeError::Missing {
            missing: missing.join(", "),
            m,
        });
    }
    shards.sort_by_key(|(_, s)| s.shard().map_or(0, |x| x.k));
    let mut it = shards.into_iter().map(|(_, s)| s);
    let mut all = it.next().ok_or(MergeError::NoFiles)?;
    for s in it {
        all.absorb(s);
    }
    all.set_shard(None);
    all.finish();
    Ok(all)
}

/// Writes `value` as pretty JSON to `path` atomically (a temporary file, then a rename), so
/// a killed process leaves no truncated result under the final name.
pub fn write_json<T: Serialize>(value: &T, path: &Path) -> Result<(), String> {
    let json = serde_json::to_string_pretty(value).map_err(|e| e.to_string())?;
    let tmp = path.with_extension("json.tmp");
    std::fs::write(&tmp, json + "\n")
        .and_then(|()| std::fs::rename(&tmp, path))
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// The items `0..n` of `shard`.
pub fn items(shard: Shard, n: u64) -> impl Iterator<Item = u64> {
    (shard.k - 1..n).step_by(shard.m as usize)
}

/// A test hook for fault tolerance: with `BILLIARDS_FAIL_ONCE_DIR` set, the first run of
/// each shard (`--shard`) of `command` creates a marker file there and fails, with exit
/// status 1, before doing any work; the next run of that shard finds the marker and works.
/// The Ray runner's tests use it to check that a failed shard is retried and the merge
/// unchanged.
pub fn fail_once(command: &str, shard: Option<Shard>) -> Result<(), String> {
    let (Some(dir), Some(shard)) = (std::env::var_os("BILLIARDS_FAIL_ONCE_DIR"), shard) else {
        return Ok(());
    };
    let marker = Path::new(&dir).join(format!("{command}-{}-of-{}", shard.k, shard.m));
    match std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&marker)
    {
        Ok(_) => Err(format!(
            "shard {shard}: failing on purpose (BILLIARDS_FAIL_ONCE_DIR; {} now marks it)",
            marker.display()
        )),
        Err(_) => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_split_the_items_exactly() {
        for m in 1..6 {
            for n in 0..20 {
                let mut seen = vec![0; n as usize];
                for k in 1..=m {
                    let s = Shard { k, m };
                    let mine: Vec<u64> = items(s, n).collect();
                    assert_eq!(mine.len() as u64, s.count(n));
                    for i in mine {
                        assert!(s.contains(i));
                        seen[i as usize] += 1;
                    }
                }
                assert!(seen.iter().all(|&c| c == 1));
            }
        }
        assert_eq!(parse_shard("2/3"), Ok(Shard { k: 2, m: 3 }));
        assert!(parse_shard("4/3").is_err() && parse_shard("0/1").is_err());
    }
}
