//! Pages being filled: the frame that holds a page's content inside its margins, header and
//! footer, and the pages laid out so far with the place where the next thing goes. The
//! document's parts (title page, blocks, tables) all fill the same pages through it.

use crate::page::{Item, Page, Pt};

/// Page margins.
pub(crate) const MARGIN: Pt = 36.0;
/// Room for the header above the content and the footer below it.
const HEADER: Pt = 20.0;
const FOOTER: Pt = 18.0;

/// Where the content of a page goes.
pub(crate) struct Frame {
    pub top: Pt,
    pub bottom: Pt,
    pub left: Pt,
    pub right: Pt,
}

impl Frame {
    pub(crate) fn new(width: Pt, height: Pt) -> Frame {
        Frame {
            top: MARGIN + HEADER,
            bottom: height - MARGIN - FOOTER,
            left: MARGIN,
            right: width - MARGIN,
        }
    }
}

/// Pages being filled.
pub(crate) struct Pages {
    pub pages: Vec<Page>,
    pub frame: Frame,
    /// Where the next thing goes on the last page.
    pub y: Pt,
}

impl Pages {
    /// Starts a new page of `section`.
    pub(crate) fn new_page(&mut self, section: &str) {
        self.pages.push(Page {
            items: Vec::new(),
            section: section.to_string(),
        });
        self.y = self.frame.top;
    }

    /// Room left on the last page.
    pub(crate) fn room(&self) -> Pt {
        self.frame.bottom - self.y
    }

    /// Whether the last page holds nothing yet.
    pub(crate) fn fresh(&self) -> bool {
        self.pages.last().is_none_or(|p| p.items.is_empty())
    }

    /// Adds items to the last page.
    pub(crate) fn put(&mut self, items: Vec<Item>) {
        if let Some(p) = self.pages.last_mut() {
            p.items.extend(items);
        }
    }
}
