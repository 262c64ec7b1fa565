//! Embeds every chart file under charts/ in the library: writes `charts.rs` in OUT_DIR with one
//! `include_str!` per file, so the library reads no files at run time.

use std::path::{Path, PathBuf};

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|x| x == "toml") {
            out.push(p);
        }
    }
}

/// The value of the first top-level `id = "..."` line (before any table header), or "".
fn declared_id(text: &str) -> String {
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            break;
        }
        let Some(rest) = line.strip_prefix("id") else {
            continue;
        };
        let Some(value) = rest.trim_start().strip_prefix('=') else {
            continue;
        };
        let value = value.trim();
        if let Some(inner) = value.strip_prefix('"').and_then(|v| v.strip_suffix('"')) {
            if !inner.contains(['\\', '"']) {
                return inner.to_string();
            }
        }
        break;
    }
    String::new()
}

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let charts = root.join("charts");
    println!("cargo:rerun-if-changed=charts");
    let mut files = Vec::new();
    collect(&charts, &mut files);
    files.sort();
    let mut code = String::from("/// Every chart file: (path under charts/, contents).\npub const CHART_FILES: &[(&str, &str)] = &[\n");
    let mut ids = String::from("/// The id each chart file declares (its top-level `id = \"...\"` line; empty when none is\n/// found), in the order of [`CHART_FILES`]: lets a lookup parse only the chart it needs.\npub const CHART_IDS: &[&str] = &[\n");
    for f in &files {
        println!("cargo:rerun-if-changed={}", f.display());
        let rel = f
            .strip_prefix(&charts)
            .unwrap_or(f)
            .to_string_lossy()
            .replace('\\', "/");
        code.push_str(&format!(
            "    ({rel:?}, include_str!({:?})),\n",
            f.display().to_string()
        ));
        let text = std::fs::read_to_string(f).unwrap_or_default();
        ids.push_str(&format!("    {:?},\n", declared_id(&text)));
    }
    code.push_str("];\n");
    ids.push_str("];\n");
    code.push_str(&ids);
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("charts.rs");
    std::fs::write(out, code).expect("write charts.rs");
}
