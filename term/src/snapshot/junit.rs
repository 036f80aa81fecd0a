//! The snapshot results as a JUnit XML report, the format CI systems read test results from (the schema of Apache
//! Ant's JUnit task: one `testsuite` of `testcase`s, each with a `failure` or an `error` when it did not pass).

use std::fmt::Write as _;

use super::outcome::{Outcome, Row};

/// The report of `rows`, which took `seconds` in all.
pub fn junit_xml(rows: &[Row], seconds: f64) -> String {
    let failures = rows.iter().filter(|r| matches!(r.outcome, Outcome::Differs { .. } | Outcome::Missing)).count();
    let errors = rows.iter().filter(|r| matches!(r.outcome, Outcome::Error(_))).count();
    let mut xml = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        xml,
        "<testsuite name=\"rastty snapshot\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" time=\"{seconds:.3}\">",
        rows.len()
    );
    for row in rows {
        let _ = write!(xml, "  <testcase classname=\"{}\" name=\"{}\"", escape(&row.file), escape(&row.view));
        match &row.outcome {
            Outcome::Error(message) => {
                let _ = writeln!(xml, ">\n    <error message=\"{}\"/>\n  </testcase>", escape(message));
            }
            outcome @ (Outcome::Differs { .. } | Outcome::Missing) => {
                let _ = writeln!(xml, ">\n    <failure message=\"{}\"/>\n  </testcase>", escape(&outcome.to_string()));
            }
            _ => xml.push_str("/>\n"),
        }
    }
    xml.push_str("</testsuite>\n");
    xml
}

/// `text` as XML attribute text: markup characters as entities, and characters XML 1.0 cannot hold (control
/// characters but tab, line feed and carriage return) as `?`.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' | '\r' => {
                let _ = write!(out, "&#{};", c as u32);
            }
            c if c.is_control() => out.push('?'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_and_control_characters_are_escaped() {
        assert_eq!(escape("a<b & \"c\"\x1b[2J\n"), "a&lt;b &amp; &quot;c&quot;?[2J&#10;");
    }
}
