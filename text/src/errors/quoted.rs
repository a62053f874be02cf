//! The engine's errors that diagnostics, refusals and the editor quote, in the user's
//! language: an address that does not read, an operand the instruction refuses, a table row
//! that does not fit, a device of the machine model that cannot be built. In English each is
//! its `Display`; the Chinese says the same specifics.

use crate::Lang;
use ladder_engine::address::AddressError;
use ladder_engine::catalog::DigitGroupError;
use ladder_engine::cnc::CncError;
use ladder_engine::compiler::OperandRefusal;
use ladder_engine::devices::{ExprError, ModelError};
use ladder_engine::model::sheets::{TableError, Taken};

/// Why an address does not read or is beyond the controller's range, in `lang`.
pub fn address_error(e: &AddressError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => e.zh(),
    }
}

/// Why an instruction refuses an operand, in `lang`.
pub fn operand_refusal(e: &OperandRefusal, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => e.zh(),
    }
}

/// The rule of an instruction's control digits, in `lang`.
pub fn digit_group_error(e: &DigitGroupError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => e.zh().to_string(),
    }
}

/// Why a table row cannot be taken, in `lang`.
pub fn table_error(e: &TableError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => e.zh(),
    }
}

/// What already holds a name or number a table row wants, in `lang`.
pub fn taken(t: &Taken, lang: Lang) -> String {
    match lang {
        Lang::En => t.to_string(),
        Lang::Zh => t.zh(),
    }
}

/// Why a device of the machine model cannot be built, in `lang`.
pub fn model_error(e: &ModelError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => e.zh(),
    }
}

/// Why a device's condition does not read, in `lang`.
pub fn expr_error(e: &ExprError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => e.zh(),
    }
}

/// Why the simulated CNC refuses a command or a key, in `lang`.
pub fn cnc_error(e: &CncError, lang: Lang) -> String {
    match lang {
        Lang::En => e.en(),
        Lang::Zh => e.zh(),
    }
}
