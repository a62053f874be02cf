//! The check every bilingual message is held to in tests: the Chinese is Chinese and says
//! the same specifics as the English. A leaf, so the tests of each part use it without
//! importing one another.

fn is_cjk(c: char) -> bool {
    ('\u{4e00}'..='\u{9fff}').contains(&c)
}

/// The runs of ASCII digits in `text`.
fn digit_runs(text: &str) -> Vec<&str> {
    text.split(|c: char| !c.is_ascii_digit())
        .filter(|s| !s.is_empty())
        .collect()
}

/// The texts between pairs of backticks.
fn quoted(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).collect()
}

/// Checks that `zh` is Chinese and carries every number and every quoted name of `en`, and
/// that outside quotes it uses full-width punctuation. The level names (`LEVEL1`, `level 2`)
/// are words in Chinese (一级程序, 二级程序), so their digits are not looked for.
pub(crate) fn assert_bilingual(en: &str, zh: &str) {
    assert!(zh.chars().any(is_cjk), "not Chinese: {zh} (English: {en})");
    let mut plain = en.to_string();
    for level in [
        "LEVEL1", "LEVEL2", "level 1", "level 2", "level-1", "level-2",
    ] {
        plain = plain.replace(level, "");
    }
    for digits in digit_runs(&plain) {
        assert!(
            digit_runs(zh).contains(&digits),
            "`{digits}` missing in: {zh} (English: {en})"
        );
    }
    for name in quoted(en) {
        assert!(
            zh.contains(&format!("`{name}`")),
            "`{name}` missing in: {zh} (English: {en})"
        );
    }
    let outside: String = zh.split('`').step_by(2).collect();
    // A quoted IL text (`NETWORK "title"`) is the user's, not the message's.
    let outside: String = outside.split('"').step_by(2).collect();
    for c in [',', ';', ':', '(', ')', '?'] {
        assert!(!outside.contains(c), "ASCII `{c}` in: {zh} (English: {en})");
    }
}
