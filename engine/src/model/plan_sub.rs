//! The subprogram plans beside the other edit plans: a new subprogram, a renumbering or
//! renaming (the block moved to keep P numbers in order, in one undo step), what the text
//! `NUMBER [NAME]` means, and why it is refused.

use super::block::{Block, BlockKind};
use super::edit::Edit;
use super::ladder::Ladder;
use crate::Area;
use crate::profile::Profile;
use thiserror::Error;

/// Why a subprogram command was refused.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum SubError {
    /// The text is not `NUMBER [NAME]` with a number in the profile's P range.
    #[error("type `NUMBER [NAME]`, e.g. 12 TOOL_CHANGE, range P{lo:04}–P{hi:04}")]
    Usage {
        /// The lowest P number.
        lo: u16,
        /// The highest P number.
        hi: u16,
    },
    /// The name is not a symbol.
    #[error(
        "`{0}` is not a valid symbol name (letters, digits, underscores, CJK; not starting with a digit)"
    )]
    BadName(String),
    /// Another subprogram has this number.
    #[error("P{0:04}: this subprogram already exists")]
    Exists(u16),
    /// The subprogram is gone.
    #[error("P{0:04}: this block no longer exists")]
    NoSuch(u16),
}

/// Reads `NUMBER [NAME]` (`12 TOOL_CHANGE`, `P0012`): a number in the profile's P range and
/// an optional symbol name.
pub fn parse_sub(text: &str, profile: &Profile) -> Result<(u16, String), SubError> {
    let mut words = text.split_whitespace();
    let number = words
        .next()
        .map(|w| w.trim_start_matches(['P', 'p']))
        .and_then(|w| w.parse::<u16>().ok());
    let name = words.collect::<Vec<_>>().join(" ");
    let (lo, hi) = profile.range(Area::P);
    let number = number
        .filter(|n| (lo..=hi).contains(n))
        .ok_or(SubError::Usage { lo, hi })?;
    if !name.is_empty() && !super::is_symbol_name(&name) {
        return Err(SubError::BadName(name));
    }
    Ok((number, name))
}

impl Ladder {
    /// A new subprogram P`number` with one empty network, in P order: where it goes and the
    /// edit that puts it there.
    pub fn plan_new_sub(&self, number: u16, name: String) -> Result<(usize, Edit), SubError> {
        if self.sub_index(number).is_some() {
            return Err(SubError::Exists(number));
        }
        let index = self.sub_insert_index(number);
        let mut block = Block::new(BlockKind::Sub { number, name });
        block.networks.push(self.new_network());
        let edit = Edit::InsertBlock {
            index,
            block: Box::new(block),
        };
        Ok((index, edit))
    }

    /// Subprogram P`old` renumbered and renamed: taken out and put back in its P place,
    /// with its networks and information, in one edit.
    pub fn plan_rename_sub(&self, old: u16, number: u16, name: String) -> Result<Edit, SubError> {
        let index = self.sub_index(old).ok_or(SubError::NoSuch(old))?;
        if self.sub_index(number).is_some_and(|i| i != index) {
            return Err(SubError::Exists(number));
        }
        let target = self.sub_insert_index(number);
        let mut block = self.blocks[index].clone();
        block.kind = BlockKind::Sub { number, name };
        let to = if target > index { target - 1 } else { target };
        Ok(Edit::Batch(vec![
            Edit::DeleteBlock { index },
            Edit::InsertBlock {
                index: to,
                block: Box::new(block),
            },
        ]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Project;

    #[test]
    fn subprograms_are_planned_in_p_order_and_refused_with_a_reason() {
        let mut p = Project::default();
        let profile = p.profile();
        assert_eq!(
            parse_sub("P12 TOOL_CHANGE", profile).unwrap(),
            (12, "TOOL_CHANGE".into())
        );
        assert!(matches!(
            parse_sub("x", profile),
            Err(SubError::Usage { .. })
        ));
        assert!(matches!(
            parse_sub("3 1BAD", profile),
            Err(SubError::BadName(_))
        ));
        for n in [20, 5] {
            let (_, edit) = p.ladder.plan_new_sub(n, String::new()).unwrap();
            p.apply_change(edit.into()).unwrap();
        }
        assert_eq!(p.ladder.sub_index(5), Some(2), "P0005 before P0020");
        assert_eq!(
            p.ladder.plan_new_sub(5, String::new()).unwrap_err(),
            SubError::Exists(5)
        );
        let edit = p.ladder.plan_rename_sub(5, 30, "LAST".into()).unwrap();
        p.apply_change(edit.into()).unwrap();
        assert_eq!(p.ladder.sub_index(30), Some(3), "moved after P0020");
        assert_eq!(
            p.ladder.plan_rename_sub(20, 30, String::new()).unwrap_err(),
            SubError::Exists(30)
        );
        assert_eq!(
            p.ladder.plan_rename_sub(99, 1, String::new()).unwrap_err(),
            SubError::NoSuch(99)
        );
    }
}
