//! The size rules of the pure crates (ARCHITECTURE.md): no source file over 600 lines and no
//! function over 120, so every file can be read whole and every function on one screen or two.
//! Checked here for this crate and for `crates/ai`, which follows the same rules.

use std::path::{Path, PathBuf};

const MAX_FILE_LINES: usize = 600;
const MAX_FN_LINES: usize = 120;

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            out.push(path);
        }
    }
}

/// A line without its comment and string literals, for counting braces.
fn code(line: &str) -> String {
    let mut out = String::new();
    let mut chars = line.chars().peekable();
    let mut in_string = false;
    while let Some(c) = chars.next() {
        match (in_string, c) {
            (true, '\\') => {
                chars.next();
            }
            (true, '"') => in_string = false,
            (true, _) => {}
            (false, '"') => in_string = true,
            (false, '/') if chars.peek() == Some(&'/') => break,
            // A character literal such as '{' is not a brace.
            (false, '\'') => {
                let rest: String = chars.clone().take(3).collect();
                if rest.len() >= 2 && (rest.as_bytes()[1] == b'\'' || rest.starts_with('\\')) {
                    while let Some(c) = chars.next() {
                        if c == '\\' {
                            chars.next();
                        } else if c == '\'' {
                            break;
                        }
                    }
                } else {
                    out.push(c);
                }
            }
            (false, _) => out.push(c),
        }
    }
    out
}

/// Every function with a body in `text`: its name and length in lines, from the line of its
/// `fn` to the line that closes its body.
fn functions(text: &str) -> Vec<(String, usize)> {
    let lines: Vec<String> = text.lines().map(code).collect();
    let mut found = Vec::new();
    for (start, line) in lines.iter().enumerate() {
        let Some(at) = line.find("fn ") else { continue };
        let before = &line[..at];
        let is_item = before.split_whitespace().all(|w| {
            ["pub", "const", "unsafe", "async", "extern", "default"].contains(&w)
                || w.starts_with("pub(")
        });
        if !is_item {
            continue;
        }
        let name: String = line[at + 3..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // Find the body's opening brace (or a `;`: a declaration without a body).
        let mut depth = 0i32;
        let mut opened = false;
        'scan: for (k, l) in lines.iter().enumerate().skip(start) {
            let from = if k == start { at } else { 0 };
            for c in l[from..].chars() {
                match c {
                    ';' if !opened && depth == 0 => break 'scan,
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => {
                        depth -= 1;
                        if opened && depth == 0 {
                            found.push((name.clone(), k - start + 1));
                            break 'scan;
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    found
}

#[test]
fn the_function_finder_measures_functions() {
    let text = "fn a() {\n    let s = \"}\";\n    if x { y }\n}\npub(crate) fn b(x: u8) -> u8\nwhere\n{\n    x\n}\nfn c();\n";
    assert_eq!(
        functions(text),
        vec![("a".to_owned(), 4), ("b".to_owned(), 5)]
    );
}

#[test]
fn no_file_over_600_lines_and_no_function_over_120() {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    // (crate, fewest source files it has: the finder is not looking in the wrong place)
    for (name, at_least) in [("physics", 20), ("ai", 8)] {
        let before = files.len();
        sources(&crates.join(name).join("src"), &mut files);
        assert!(
            files.len() - before > at_least,
            "crates/{name}'s sources were not found"
        );
    }
    let mut too_long = Vec::new();
    let mut longest = (String::new(), 0);
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let name = file.display().to_string();
        let lines = text.lines().count();
        if lines > MAX_FILE_LINES {
            too_long.push(format!("{name}: {lines} lines"));
        }
        for (function, length) in functions(&text) {
            if length > longest.1 {
                longest = (format!("{name}: fn {function}"), length);
            }
            if length > MAX_FN_LINES {
                too_long.push(format!("{name}: fn {function} is {length} lines"));
            }
        }
    }
    assert!(too_long.is_empty(), "{too_long:#?}");
    // The finder is not blind: the longest function is of a plausible length.
    assert!(longest.1 > 60, "longest function found: {longest:?}");
}
