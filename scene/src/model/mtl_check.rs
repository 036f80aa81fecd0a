//! A line-by-line check of MTL text before it reaches `tobj`: statements `tobj` would reject (failing the whole
//! library) or panic on are dropped with a warning, so the other materials of the file still load.

use std::path::Path;

use crate::escaped::{Escaped, path_text};

/// MTL text ready for `tobj::load_mtl_buf`, and the warnings about dropped statements.
pub(crate) struct CheckedMtl {
    /// The statements to parse, one per line (dropped statements leave an empty line).
    pub(crate) text: String,
    /// One line per dropped statement, naming the file (`describe`d path) and the line.
    pub(crate) warnings: Vec<String>,
}

/// Checks MTL `bytes` (invalid UTF-8 is replaced by U+FFFD).
///
/// Rules, mirroring `tobj` 4.0.5's `parse_mtl_line`:
/// - `Ka`, `Kd`, `Ks`, `Ke` need three numbers; one number `r` is accepted as `r r r` (the MTL specification's
///   short form); anything else is dropped. (`tobj` panics on fewer than three words.)
/// - `Ns`, `Ni`, `d` need a number, `illum` an integer 0 to 255, `newmtl` a name, `map_*`/`bump` a file name.
pub(crate) fn check_mtl(describe: &Path, bytes: &[u8]) -> CheckedMtl {
    let mut text = String::with_capacity(bytes.len() + 16);
    let mut warnings = Vec::new();
    for (index, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let line = String::from_utf8_lossy(raw);
        let line = line.trim();
        match check_statement(line) {
            Ok(Statement::Keep) => text.push_str(line),
            Ok(Statement::Replace(replacement)) => text.push_str(&replacement),
            Err(problem) => warnings.push(format!(
                "{}, line {}: {}; statement ignored",
                path_text(describe),
                index + 1,
                Escaped(&problem)
            )),
        }
        text.push('\n');
    }
    CheckedMtl { text, warnings }
}

enum Statement {
    Keep,
    Replace(String),
}

fn check_statement(line: &str) -> Result<Statement, String> {
    let mut words = line.split_whitespace();
    let Some(keyword) = words.next() else { return Ok(Statement::Keep) };
    let rest = line[keyword.len()..].trim();
    match keyword {
        "newmtl" if rest.is_empty() => Err("newmtl without a material name".into()),
        "Ka" | "Kd" | "Ks" | "Ke" => {
            let numbers: Vec<&str> = words.take(3).collect();
            let parsed = numbers.iter().all(|w| w.parse::<f32>().is_ok());
            match numbers.len() {
                3 if parsed => Ok(Statement::Keep),
                1 if parsed => Ok(Statement::Replace(format!("{keyword} {0} {0} {0}", numbers[0]))),
                _ => Err(format!("{keyword} needs three numbers, found {rest:?}")),
            }
        }
        "Ns" | "Ni" | "d" => match words.next().map(str::parse::<f32>) {
            Some(Ok(_)) => Ok(Statement::Keep),
            _ => Err(format!("{keyword} needs a number, found {rest:?}")),
        },
        "illum" => match words.next().map(str::parse::<u8>) {
            Some(Ok(_)) => Ok(Statement::Keep),
            _ => Err(format!("illum needs an integer from 0 to 255, found {rest:?}")),
        },
        "map_Ka" | "map_Kd" | "map_Ks" | "map_Bump" | "map_bump" | "map_Ns" | "map_ns" | "map_NS" | "bump"
        | "map_d"
            if rest.is_empty() =>
        {
            Err(format!("{keyword} without a file name"))
        }
        _ => Ok(Statement::Keep),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(text: &str) -> CheckedMtl {
        check_mtl(Path::new("m.mtl"), text.as_bytes())
    }

    #[test]
    fn good_statements_pass_unchanged() {
        let c = check("newmtl a\nKd 0.1 0.2 0.3\nmap_Kd -s 1 1 1 a.png\n  illum 2\n");
        assert_eq!(c.text, "newmtl a\nKd 0.1 0.2 0.3\nmap_Kd -s 1 1 1 a.png\nillum 2\n\n");
        assert!(c.warnings.is_empty());
    }

    #[test]
    fn short_colours_are_completed_or_dropped_with_the_line() {
        let c = check("newmtl a\nKd 0.5\r\nKs 1 2\nKa x y z\n");
        assert_eq!(c.text, "newmtl a\nKd 0.5 0.5 0.5\n\n\n\n");
        assert_eq!(c.warnings.len(), 2);
        assert!(c.warnings[0].starts_with("m.mtl, line 3: Ks needs three numbers"), "{}", c.warnings[0]);
        assert!(c.warnings[1].starts_with("m.mtl, line 4: Ka needs three numbers"), "{}", c.warnings[1]);
    }

    #[test]
    fn other_bad_statements_are_dropped() {
        let c = check("newmtl\nNs high\nillum 300\nmap_Kd   \nd\n");
        assert_eq!(c.warnings.len(), 5, "{:?}", c.warnings);
        assert!(c.text.trim().is_empty());
    }

    #[test]
    fn control_characters_in_warnings_are_escaped() {
        let c = check("Ns \u{1b}[2J\n");
        assert!(!c.warnings[0].chars().any(char::is_control), "{:?}", c.warnings);
    }
}
