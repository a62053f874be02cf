//! Splitting a script line into words: a double-quoted string is one word and may hold
//! spaces, `;` and `#`; outside quotes `;` or `#` starts a comment.

use super::QuoteError;

/// The words of one line, or why it cannot be split.
pub fn words(line: &str) -> Result<Vec<&str>, QuoteError> {
    let mut out = Vec::new();
    let mut rest = line;
    loop {
        rest = rest.trim_start();
        let Some(c) = rest.chars().next() else { break };
        match c {
            ';' | '#' => break,
            '"' => {
                let body = &rest[1..];
                let end = body.find('"').ok_or(QuoteError::Unclosed)?;
                out.push(&body[..end]);
                rest = &body[end + 1..];
                if rest.starts_with(|c: char| !c.is_whitespace() && c != ';' && c != '#') {
                    return Err(QuoteError::NoSpaceAfter);
                }
            }
            _ => {
                let end = rest
                    .find(|c: char| c.is_whitespace() || c == ';' || c == '#' || c == '"')
                    .unwrap_or(rest.len());
                if rest[end..].starts_with('"') {
                    return Err(QuoteError::InsideWord);
                }
                out.push(&rest[..end]);
                rest = &rest[end..];
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::{QuoteError, words};

    #[test]
    fn quotes_keep_spaces_and_comment_marks() {
        assert_eq!(
            words(r#"cnc program "O0001; M03 S800 # x" ; comment"#).unwrap(),
            vec!["cnc", "program", "O0001; M03 S800 # x"]
        );
        assert_eq!(words("set X0.0 1 # c").unwrap(), vec!["set", "X0.0", "1"]);
        assert_eq!(words(r#"cnc mdi """#).unwrap(), vec!["cnc", "mdi", ""]);
        assert_eq!(words(r#"cnc program "M03"#), Err(QuoteError::Unclosed));
        assert_eq!(
            words(r#"cnc program "M03"x"#),
            Err(QuoteError::NoSpaceAfter)
        );
        assert_eq!(words(r#"cnc program x"M03""#), Err(QuoteError::InsideWord));
    }
}
