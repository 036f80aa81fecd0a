//! The file name of an MTL texture statement (`map_Kd [options] file`): options skipped, backslashes turned into
//! slashes.

use std::path::PathBuf;

/// The file named by the arguments of a `map_*` statement, or `None` when only options are given.
///
/// `tobj` keeps everything after the keyword, so `map_Kd -s 2 2 1 wood.png` reaches here whole. The options of the
/// MTL specification are skipped with their arguments (`-o`, `-s`, `-t` take one to three numbers, `-mm` two, the
/// others one); the rest of the line, spaces included, is the file name. A first word that starts with `-` but is
/// no known option begins the file name. Backslashes (from Windows exporters) become `/`.
pub(crate) fn map_file(arguments: &str) -> Option<PathBuf> {
    let mut rest = arguments.trim();
    while let Some((word, after)) = split_word(rest) {
        let Some(takes) = option_arguments(word) else { break };
        rest = after;
        match takes {
            Arguments::Fixed(n) => {
                for _ in 0..n {
                    rest = split_word(rest).map_or("", |(_, after)| after);
                }
            }
            Arguments::UpToThreeNumbers => {
                for _ in 0..3 {
                    match split_word(rest) {
                        Some((w, after)) if w.parse::<f32>().is_ok() => rest = after,
                        _ => break,
                    }
                }
            }
        }
    }
    let name = rest.trim();
    (!name.is_empty()).then(|| PathBuf::from(name.replace('\\', "/")))
}

enum Arguments {
    Fixed(usize),
    UpToThreeNumbers,
}

fn option_arguments(word: &str) -> Option<Arguments> {
    Some(match word {
        "-blendu" | "-blendv" | "-bm" | "-boost" | "-cc" | "-clamp" | "-imfchan" | "-texres" | "-type" => {
            Arguments::Fixed(1)
        }
        "-mm" => Arguments::Fixed(2),
        "-o" | "-s" | "-t" => Arguments::UpToThreeNumbers,
        _ => return None,
    })
}

/// The first whitespace-separated word of `s` and the text after it (leading whitespace trimmed).
fn split_word(s: &str) -> Option<(&str, &str)> {
    let s = s.trim_start();
    if s.is_empty() {
        return None;
    }
    let end = s.find(char::is_whitespace).unwrap_or(s.len());
    Some((&s[..end], s[end..].trim_start()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(args: &str) -> Option<String> {
        map_file(args).map(|p| p.to_string_lossy().into_owned())
    }

    #[test]
    fn plain_names_are_kept_with_their_spaces() {
        assert_eq!(file("wood.png").as_deref(), Some("wood.png"));
        assert_eq!(file("  my texture.png ").as_deref(), Some("my texture.png"));
    }

    #[test]
    fn options_are_skipped() {
        assert_eq!(file("-s 2 2 1 -o 0.5 wood.png").as_deref(), Some("wood.png"));
        assert_eq!(file("-clamp on -mm 0 1 -bm 0.5 tex/a.tga").as_deref(), Some("tex/a.tga"));
        assert_eq!(file("-blendu off -t 1 1.png").as_deref(), Some("1.png"));
    }

    #[test]
    fn backslashes_become_slashes() {
        assert_eq!(file("textures\\wood.png").as_deref(), Some("textures/wood.png"));
    }

    #[test]
    fn unknown_dash_words_start_the_name_and_options_alone_name_nothing() {
        assert_eq!(file("-weird.png").as_deref(), Some("-weird.png"));
        assert_eq!(file("-s 1 1 1"), None);
        assert_eq!(file(""), None);
    }
}
