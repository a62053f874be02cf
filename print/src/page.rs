//! The laid-out document: pages of lines, paths and text in points, top-left origin, y down.
//! Both writers (PDF and SVG) draw exactly these items, so what the preview shows is what
//! prints.

/// A point on the page, in points (1/72 inch).
pub type Pt = f32;

/// How a text is placed against its x.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// x is the left end.
    Left,
    /// x is the middle.
    Middle,
    /// x is the right end.
    Right,
}

/// A shade of ink: printed documents stay black and grey.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ink {
    /// Black: the ladder and its labels.
    Black,
    /// Grey: comments, headers, rules.
    Grey,
}

impl Ink {
    /// The ink as 8-bit grey.
    pub fn grey(self) -> u8 {
        match self {
            Ink::Black => 0,
            Ink::Grey => 96,
        }
    }
}

/// One piece of a path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// Start a new sub-path.
    Move(Pt, Pt),
    /// A straight line.
    Line(Pt, Pt),
    /// A cubic Bézier curve: two control points and the end.
    Cubic(Pt, Pt, Pt, Pt, Pt, Pt),
}

/// What a page holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A stroked path.
    Path {
        /// Its pieces.
        segs: Vec<Seg>,
        /// Line width.
        width: Pt,
        /// Colour.
        ink: Ink,
    },
    /// One line of text; `y` is the baseline.
    Text {
        /// Where.
        x: Pt,
        /// Baseline.
        y: Pt,
        /// Font size.
        size: Pt,
        /// How it sits against x.
        anchor: Anchor,
        /// Colour.
        ink: Ink,
        /// The text.
        text: String,
    },
}

impl Item {
    /// A straight line.
    pub fn line(x1: Pt, y1: Pt, x2: Pt, y2: Pt, width: Pt) -> Item {
        Item::Path {
            segs: vec![Seg::Move(x1, y1), Seg::Line(x2, y2)],
            width,
            ink: Ink::Black,
        }
    }

    /// A rectangle's outline.
    pub fn rect(x: Pt, y: Pt, w: Pt, h: Pt, width: Pt, ink: Ink) -> Item {
        Item::Path {
            segs: vec![
                Seg::Move(x, y),
                Seg::Line(x + w, y),
                Seg::Line(x + w, y + h),
                Seg::Line(x, y + h),
                Seg::Line(x, y),
            ],
            width,
            ink,
        }
    }

    /// A text item.
    pub fn text(x: Pt, y: Pt, size: Pt, anchor: Anchor, ink: Ink, text: impl Into<String>) -> Item {
        Item::Text {
            x,
            y,
            size,
            anchor,
            ink,
            text: text.into(),
        }
    }
}

/// One page.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Page {
    /// What is drawn, in order.
    pub items: Vec<Item>,
    /// The block (or table) the page shows, for its header.
    pub section: String,
}

impl Page {
    /// Every text on the page, in drawing order (for tests and search).
    pub fn texts(&self) -> impl Iterator<Item = &str> {
        self.items.iter().filter_map(|i| match i {
            Item::Text { text, .. } => Some(text.as_str()),
            Item::Path { .. } => None,
        })
    }
}

/// A laid-out document.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    /// Page width.
    pub width: Pt,
    /// Page height.
    pub height: Pt,
    /// The pages, title page first.
    pub pages: Vec<Page>,
    /// The document's title (the project's name).
    pub title: String,
}
