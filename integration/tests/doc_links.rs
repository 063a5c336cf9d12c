//! Every relative link of the project's markdown pages leads somewhere: the
//! file exists, and an anchor (`page.md#heading` or `#heading`) names a
//! heading of that page (GitHub's slugs: lower case, spaces to hyphens,
//! punctuation dropped).

use std::path::{Path, PathBuf};

const PAGES: &[&str] = &[
    "README.md",
    "BENCHMARKS.md",
    "ARCHITECTURE.md",
    "CHANGELOG.md",
    "docs",
    "examples/data/README.md",
    "tests/data/README.md",
    "cli/README.md",
];

/// The repository (this test's package is `integration/` in it).
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The markdown files of `PAGES` (a folder stands for its `*.md`).
fn pages() -> Vec<PathBuf> {
    let mut out = Vec::new();
    for page in PAGES {
        let path = root().join(page);
        if path.is_dir() {
            let mut found: Vec<PathBuf> = std::fs::read_dir(&path)
                .expect("a readable folder")
                .map(|e| e.expect("an entry").path())
                .filter(|p| p.extension().is_some_and(|e| e == "md"))
                .collect();
            found.sort();
            out.extend(found);
        } else if path.exists() {
            out.push(path);
        }
    }
    out
}

/// GitHub's anchor of a heading.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a page's headings (outside code blocks).
fn anchors(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = Vec::new();
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            out.push(slug(line.trim_start_matches('#')));
        }
    }
    out
}

/// The targets of the page's inline links and images, outside code.
fn links(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = Vec::new();
    // a link's text may wrap onto the next line; its target does not
    let mut prose = String::new();
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            prose += line;
            prose.push('\n');
        }
    }
    let prose: String = prose.split('`').enumerate().filter(|(i, _)| i % 2 == 0).map(|(_, s)| s).collect();
    let mut rest = prose.as_str();
    while let Some(i) = rest.find("](") {
        rest = &rest[i + 2..];
        if let Some(end) = rest.find(')') {
            out.push(rest[..end].trim().to_string());
            rest = &rest[end..];
        }
    }
    out
}

#[test]
fn relative_links_resolve() {
    let mut broken = Vec::new();
    let pages = pages();
    assert!(pages.len() > 5, "found the pages");
    for page in &pages {
        let text = std::fs::read_to_string(page).expect("a readable page");
        for target in links(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (file, anchor) = match target.split_once('#') {
                Some((f, a)) => (f, Some(a)),
                None => (target.as_str(), None),
            };
            let path = if file.is_empty() { page.clone() } else { page.parent().unwrap_or(Path::new(".")).join(file) };
            if !path.exists() {
                broken.push(format!("{}: {target} (no such file)", page.display()));
                continue;
            }
            if let Some(anchor) = anchor {
                if path.extension().is_some_and(|e| e == "md") {
                    let heads = anchors(&std::fs::read_to_string(&path).expect("a readable page"));
                    if !heads.iter().any(|h| h == anchor) {
                        broken.push(format!("{}: {target} (no such heading)", page.display()));
                    }
                }
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}
