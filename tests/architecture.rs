//! The game's layout rules, read from its source files (ARCHITECTURE.md):
//! - no import cycle among the files of `src/`, nor among its top-level modules;
//! - every egui call lives under `src/ui/`.
//!
//! A file depends on another when it names an item of it through `crate::`, `super::`,
//! `self::` or (in a module with children) a child's name; declaring a child (`mod x;`) is not
//! a use, nor is anything in the file's unit tests.

use std::{
    collections::{BTreeMap, BTreeSet},
    path::{Path, PathBuf},
};

fn src_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The `src/` folders of the workspace's crates (issue 50: the rules hold in every crate).
fn crate_src_dirs() -> Vec<PathBuf> {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates");
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(crates)
        .unwrap()
        .map(|e| e.unwrap().path().join("src"))
        .filter(|p| p.is_dir())
        .collect();
    dirs.sort();
    dirs
}

/// Every `.rs` file under `dir`, as paths relative to `root`.
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(root, &path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            out.push(path.strip_prefix(root).unwrap().to_path_buf());
        }
    }
}

/// The module path of a file: `ui/hud.rs` is `[ui, hud]`, `ui/mod.rs` is `[ui]`, `lib.rs` is
/// the crate root `[]`.
fn module_of(file: &Path) -> Vec<String> {
    let mut parts: Vec<String> = file
        .with_extension("")
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    if parts == ["lib"] || parts == ["main"] {
        parts.clear();
    }
    parts
}

/// The file of `root` that defines the longest prefix of `path` that is a module.
fn file_of(root: &Path, path: &[String]) -> Option<PathBuf> {
    (1..=path.len()).rev().find_map(|k| {
        let base: PathBuf = path[..k].iter().collect();
        [base.with_extension("rs"), base.join("mod.rs")]
            .into_iter()
            .find(|f| root.join(f).is_file())
    })
}

/// Source without comments or string literals (their text is not code).
fn code_of(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '/' if chars.peek() == Some(&'/') => {
                for c in chars.by_ref() {
                    if c == '\n' {
                        out.push('\n');
                        break;
                    }
                }
            }
            '"' => {
                while let Some(c) = chars.next() {
                    match c {
                        '\\' => {
                            chars.next();
                        }
                        '"' => break,
                        _ => {}
                    }
                }
                out.push_str("\"\"");
            }
            _ => out.push(c),
        }
    }
    out
}

/// Expands a use tree (`crate::{a::{b, c}, d}`) into its paths.
fn expand_use(prefix: &str, tree: &str, out: &mut Vec<String>) {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        if !tree.is_empty() {
            let path = tree.split(" as ").next().unwrap();
            out.push(format!("{prefix}{path}"));
        }
        return;
    };
    let head = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap()];
    let (mut depth, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                expand_use(&format!("{prefix}{head}"), &inner[start..i], out);
                start = i + 1;
            }
            _ => {}
        }
    }
    expand_use(&format!("{prefix}{head}"), &inner[start..], out);
}

/// The paths a file names: every `use` tree, and every path written in place.
fn paths_in(code: &str, children: &[String]) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let before_ok = at == 0 || !rest.as_bytes()[at - 1].is_ascii_alphanumeric();
        let end = rest[at..].find(';').map_or(rest.len(), |e| at + e);
        if before_ok {
            expand_use("", &rest[at + 4..end], &mut paths);
        }
        rest = &rest[at + 4..];
    }
    // Paths written in place: `crate::a::b`, `super::x`, or a child's name followed by `::`.
    let bytes = code.as_bytes();
    let mut i = 0;
    while i < code.len() {
        let word_start = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        let after_colons = i >= 2 && &code[i - 2..i] == "::";
        if word_start && !after_colons {
            let end = code[i..]
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| i + e);
            let path = &code[i..end];
            let first = path.split("::").next().unwrap();
            let rooted = ["crate", "super", "self"].contains(&first)
                || children.iter().any(|child| child == first);
            // `use super::{..}` leaves `super::` here: the tree itself is read above.
            if path.contains("::") && !path.ends_with("::") && rooted {
                paths.push(path.to_owned());
            }
            i = end.max(i + 1);
        } else {
            i += 1;
        }
    }
    paths
        .into_iter()
        .map(|p| {
            p.split("::")
                .map(|s| s.trim().to_owned())
                .filter(|s| !s.is_empty())
                .collect()
        })
        .collect()
}

/// Resolves a path named in module `me` (defined in `file`) to the module path it points in.
fn resolve(me: &[String], file: &Path, path: &[String], children: &[String]) -> Vec<String> {
    let own = file
        .file_name()
        .is_some_and(|f| f == "mod.rs" || f == "lib.rs");
    let mut base: Vec<String> = me.to_vec();
    let mut segs = path;
    match segs.first().map(String::as_str) {
        Some("crate") => {
            base.clear();
            segs = &segs[1..];
        }
        Some("self") => segs = &segs[1..],
        Some("super") => {
            while segs.first().is_some_and(|s| s == "super") {
                base.pop();
                segs = &segs[1..];
            }
        }
        Some(first) if children.iter().any(|c| c == first) && own => {}
        _ => {}
    }
    base.extend(segs.iter().cloned());
    base
}

/// Every file's dependencies on other files of the crate source folder `root`.
fn dependency_graph(root: &Path) -> BTreeMap<PathBuf, BTreeSet<PathBuf>> {
    let mut files = Vec::new();
    rust_files(root, root, &mut files);
    let mut graph = BTreeMap::new();
    for file in files {
        let code = code_of(&std::fs::read_to_string(root.join(&file)).unwrap());
        // A file's inline unit tests (`mod tests { .. }`, last in the file) are not part of the
        // layout: their `use super::*` names the file itself, which the scanner would read as its
        // parent. A `mod tests;` declared in its own file cuts nothing (what follows it is code);
        // that file is scanned as any other.
        let code = match code.find("#[cfg(test)]\nmod tests {") {
            Some(at) => code[..at].to_owned(),
            None => code,
        };
        let children: Vec<String> = code
            .lines()
            .filter_map(|line| {
                let line = line.trim().strip_prefix("pub ").unwrap_or(line.trim());
                let name = line.strip_prefix("mod ")?.strip_suffix(';')?;
                Some(name.trim().to_owned())
            })
            .collect();
        let me = module_of(&file);
        let deps: BTreeSet<PathBuf> = paths_in(&code, &children)
            .iter()
            .map(|path| resolve(&me, &file, path, &children))
            .filter_map(|target| file_of(root, &target))
            .filter(|target| *target != file)
            .collect();
        graph.insert(file, deps);
    }
    graph
}

/// The groups of nodes that reach each other (Tarjan), of two nodes or more.
fn cycles<N: Ord + Clone>(graph: &BTreeMap<N, BTreeSet<N>>) -> Vec<Vec<N>> {
    struct Walk<'g, N> {
        graph: &'g BTreeMap<N, BTreeSet<N>>,
        index: BTreeMap<N, usize>,
        low: BTreeMap<N, usize>,
        stack: Vec<N>,
        found: Vec<Vec<N>>,
    }
    impl<N: Ord + Clone> Walk<'_, N> {
        fn visit(&mut self, v: &N) {
            let n = self.index.len();
            self.index.insert(v.clone(), n);
            self.low.insert(v.clone(), n);
            self.stack.push(v.clone());
            for w in self.graph.get(v).into_iter().flatten() {
                if !self.index.contains_key(w) {
                    self.visit(w);
                    let low = self.low[v].min(self.low[w]);
                    self.low.insert(v.clone(), low);
                } else if self.stack.contains(w) {
                    let low = self.low[v].min(self.index[w]);
                    self.low.insert(v.clone(), low);
                }
            }
            if self.low[v] == self.index[v] {
                let at = self.stack.iter().position(|x| x == v).unwrap();
                let group = self.stack.split_off(at);
                if group.len() > 1 {
                    self.found.push(group);
                }
            }
        }
    }
    let mut walk = Walk {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in graph.keys() {
        if !walk.index.contains_key(v) {
            walk.visit(v);
        }
    }
    walk.found
}

#[test]
fn no_import_cycle_among_the_files_of_src() {
    let graph = dependency_graph(&src_dir());
    // The scanner sees real imports (a check that it is not blind).
    let ui = &graph[Path::new("ui/settings/shot.rs")];
    assert!(ui.contains(Path::new("ui/layout.rs")), "{ui:?}");
    assert!(ui.contains(Path::new("sim/mod.rs")), "{ui:?}");
    assert!(graph[Path::new("ui/mod.rs")].contains(Path::new("ui/hud.rs")));
    let found = cycles(&graph);
    assert!(found.is_empty(), "import cycles among files: {found:?}");
}

#[test]
fn no_import_cycle_among_the_top_level_modules() {
    let top = |f: &Path| {
        let first = f.iter().next().unwrap().to_string_lossy().into_owned();
        first.trim_end_matches(".rs").to_owned()
    };
    let mut modules: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, deps) in dependency_graph(&src_dir()) {
        let me = top(&file);
        let entry = modules.entry(me.clone()).or_default();
        entry.extend(deps.iter().map(|d| top(d)).filter(|d| *d != me));
    }
    let found = cycles(&modules);
    assert!(found.is_empty(), "import cycles among modules: {found:?}");
}

/// Issue 50: no import cycle among the files of any crate of the workspace either.
#[test]
fn no_import_cycle_among_the_files_of_each_crate() {
    // The scanner sees the crates' imports (a check that it is not blind there either).
    let rules = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/rules/src");
    let eight_ball = &dependency_graph(&rules)[Path::new("eight_ball.rs")];
    assert!(eight_ball.contains(Path::new("state.rs")), "{eight_ball:?}");
    // Nor past a `mod tests;` declared in the middle of a file (the code after it counts).
    let physics = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/physics/src");
    let mathavan = &dependency_graph(&physics)[Path::new("resolve/mathavan_2010/mod.rs")];
    assert!(
        mathavan.contains(Path::new("resolve/ball_cushion.rs")),
        "{mathavan:?}"
    );
    let mut found = Vec::new();
    for root in crate_src_dirs() {
        let graph = dependency_graph(&root);
        for cycle in cycles(&graph) {
            // The edges inside the cycle, to see which import to move.
            let edges: Vec<String> = cycle
                .iter()
                .flat_map(|a| {
                    graph[a]
                        .iter()
                        .filter(|b| cycle.contains(b))
                        .map(move |b| format!("{} -> {}", a.display(), b.display()))
                })
                .collect();
            found.push(format!("{}: {}", root.display(), edges.join(", ")));
        }
    }
    assert!(
        found.is_empty(),
        "import cycles among files:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_cycle_finder_finds_cycles() {
    let graph: BTreeMap<u8, BTreeSet<u8>> = [
        (1, BTreeSet::from([2])),
        (2, BTreeSet::from([3])),
        (3, BTreeSet::from([1])),
        (4, BTreeSet::from([1])),
    ]
    .into();
    let found = cycles(&graph);
    assert_eq!(found.len(), 1);
    assert_eq!(
        found[0].iter().copied().collect::<BTreeSet<_>>(),
        [1, 2, 3].into()
    );
}

#[test]
fn egui_is_used_only_under_src_ui() {
    let mut files = Vec::new();
    rust_files(&src_dir(), &src_dir(), &mut files);
    let outside: Vec<_> = files
        .iter()
        .filter(|f| !f.starts_with("ui"))
        .filter(|f| {
            let code = code_of(&std::fs::read_to_string(src_dir().join(f)).unwrap());
            code.contains("egui")
        })
        .collect();
    assert!(outside.is_empty(), "egui outside src/ui: {outside:?}");
}
