//! An I/O error's reason in the user's language: the system's reasons stay as the system
//! said them; the engine's own reasons carried inside an I/O error (a file past the size
//! limit, [`TooLarge`]) are worded here.

use crate::Lang;
use ladder_engine::file::TooLarge;

/// The reason of an I/O error, in `lang` where it is the engine's, else as the system said it.
pub fn io_error(e: &std::io::Error, lang: Lang) -> String {
    let ours = e.get_ref().and_then(|r| r.downcast_ref::<TooLarge>());
    match (ours, lang) {
        (Some(TooLarge { mib }), Lang::Zh) => {
            format!("文件大于 {mib} MiB，超出 Ladder Studio 能读取的上限")
        }
        _ => e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Error, ErrorKind};

    #[test]
    fn the_engine_s_reason_reads_in_chinese_and_the_system_s_stays() {
        let big = Error::new(ErrorKind::FileTooLarge, TooLarge { mib: 64 });
        assert_eq!(
            io_error(&big, Lang::En),
            "the file is larger than 64 MiB, the most Ladder Studio reads"
        );
        let zh = io_error(&big, Lang::Zh);
        assert!(crate::errors::has_cjk(&zh) && zh.contains("64"), "{zh}");
        assert!(!zh.contains("larger"), "{zh}");
        let os = Error::from(ErrorKind::NotFound);
        assert_eq!(io_error(&os, Lang::Zh), os.to_string());
    }
}
