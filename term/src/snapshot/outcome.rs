//! What became of each picture, and the table `rastty snapshot` prints of them.

use std::fmt;

use rastty_scene::escaped::Escaped;

/// What became of one picture (or of a file none of whose pictures could be made).
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Written (no `--check`).
    Written,
    /// Equal to the stored picture (within the tolerance).
    Matches,
    /// Different from the stored picture, and written over it (`--update`).
    Updated {
        /// Pixels that differed.
        differing: u64,
    },
    /// Different from the stored picture (`--check`): the new one and a diff image written beside it.
    Differs {
        /// Pixels beyond the tolerance, or every pixel for a picture of another size.
        differing: u64,
        /// The largest Oklab distance of a pixel's colours (none for another size).
        largest: Option<f32>,
        /// Why, when it is not the colours: the stored picture's other size.
        reason: Option<String>,
    },
    /// No stored picture to compare with (`--check`): the new one written beside where it would be.
    Missing,
    /// The model could not be loaded or drawn, or a picture not read or written: the message, raw.
    Error(String),
}

impl Outcome {
    /// Whether the run should fail for it.
    pub fn fails(&self) -> bool {
        matches!(self, Self::Differs { .. } | Self::Missing | Self::Error(_))
    }
}

impl fmt::Display for Outcome {
    /// A short description, text from files escaped.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Written => f.write_str("written"),
            Self::Matches => f.write_str("matches"),
            Self::Updated { differing } => write!(f, "updated ({differing} pixels differed)"),
            Self::Differs { reason: Some(reason), .. } => write!(f, "differs: {}", Escaped(reason)),
            Self::Differs { differing, largest, .. } => {
                write!(f, "differs in {differing} pixels")?;
                if let Some(largest) = largest {
                    write!(f, ", by up to {largest:.3} in Oklab")?;
                }
                Ok(())
            }
            Self::Missing => f.write_str("no stored picture"),
            Self::Error(message) => write!(f, "error: {}", Escaped(message)),
        }
    }
}

/// One picture's row: the file and view it is of, and what became of it.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The model or scene file as named (or found in a folder), raw.
    pub file: String,
    /// The view's name, or `-` for a file that failed as a whole.
    pub view: String,
    /// What became of it.
    pub outcome: Outcome,
}

/// The table of the rows that fail (file, view, differing pixels, largest difference, what happened), and a line
/// counting every outcome: what `rastty snapshot` prints. Text from files is escaped.
pub fn table(rows: &[Row]) -> String {
    let mut out = String::new();
    let failing: Vec<&Row> = rows.iter().filter(|r| r.outcome.fails()).collect();
    if !failing.is_empty() {
        out.push_str("| file | view | differing pixels | largest difference | result |\n|---|---|---:|---:|---|\n");
        for row in failing {
            let (differing, largest) = match &row.outcome {
                Outcome::Differs { differing, largest, .. } => {
                    (differing.to_string(), largest.map_or_else(|| "-".into(), |l| format!("{l:.3}")))
                }
                _ => ("-".into(), "-".into()),
            };
            out.push_str(&format!(
                "| {} | {} | {differing} | {largest} | {} |\n",
                Escaped(&row.file),
                Escaped(&row.view),
                row.outcome
            ));
        }
    }
    let count = |f: fn(&Outcome) -> bool| rows.iter().filter(|r| f(&r.outcome)).count();
    let parts = [
        (count(|o| matches!(o, Outcome::Written)), "written"),
        (count(|o| matches!(o, Outcome::Matches)), "matching"),
        (count(|o| matches!(o, Outcome::Updated { .. })), "updated"),
        (count(|o| matches!(o, Outcome::Differs { .. })), "differing"),
        (count(|o| matches!(o, Outcome::Missing)), "missing"),
        (count(|o| matches!(o, Outcome::Error(_))), "failed"),
    ];
    let said: Vec<String> = parts.iter().filter(|(n, _)| *n > 0).map(|(n, what)| format!("{n} {what}")).collect();
    let plural = if rows.len() == 1 { "" } else { "s" };
    let said = if said.is_empty() { "none".into() } else { said.join(", ") };
    out.push_str(&format!("{} picture{plural}: {said}\n", rows.len()));
    out
}
