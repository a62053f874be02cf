//! Every user action of the editor as one value of one enum: its text (through [`Msg`]), its
//! keyboard shortcut (which both binds the key and is shown beside the menu entry) and where it
//! appears. Menus, toolbars, keys, right-click menus and the Help list of shortcuts are all
//! built from this module; `dispatch.rs` says whether a command is enabled now and runs it
//! after the frame. A leaf module: it knows nothing of the application's state.

use super::i18n::{Lang, Msg};
use super::place::BlockKey;
use super::place::View;
use super::settings::DisplayMode;
use egui::{Key, KeyboardShortcut, ModifierNames, Modifiers};

/// A Help window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HelpPage {
    /// The keys.
    Shortcuts,
    /// Every instruction with its operands, from the catalogue.
    Instructions,
    /// Version and licence.
    About,
}

/// A direction of the arrow keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    /// ←.
    Left,
    /// →.
    Right,
    /// ↑.
    Up,
    /// ↓.
    Down,
}

impl Dir {
    /// Rows and columns moved.
    pub fn delta(self) -> (i32, i32) {
        match self {
            Dir::Left => (0, -1),
            Dir::Right => (0, 1),
            Dir::Up => (-1, 0),
            Dir::Down => (1, 0),
        }
    }
}

macro_rules! commands {
    (
        $( $(#[$m:meta])* $name:ident => $msg:ident $(, $mods:ident $key:ident)? ; )*
    ) => {
        /// One user action of the editor.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Command {
            $( $(#[$m])* $name, )*
            /// Open a recent project (index in the recent list).
            OpenRecent(usize),
            /// List the calls of subprogram P`0` in the output window.
            ViewCalls(u16),
            /// Renumber or rename subprogram P`0`.
            RenameSub(u16),
            /// Delete subprogram P`0`.
            DeleteSub(u16),
            /// Edit a block's information text.
            BlockInfo(BlockKey),
            /// Switch the UI language.
            Language(Lang),
            /// How operands are shown.
            Display(DisplayMode),
            /// Show a view.
            ShowView(View),
            /// The answer to the first force's question: force (true) or not.
            ConfirmForces(bool),
            /// Zoom to `0` percent.
            ZoomTo(u16),
            /// Go to row `0` (0-based) of the table shown (Ctrl+G in a table view).
            GoToRow(usize),
            /// Ask where to write the trace page's CSV (its data waits in the online state).
            ExportTraceCsv,
            /// Show a cell: its block, scrolled to it, the cursor on it (a feature's jump).
            ShowCell(ladder_engine::model::CellRef),
            /// Open a Help window.
            Help(HelpPage),
            /// Move the cursor.
            Move(Dir),
            /// Grow the selection.
            Extend(Dir),
            /// The online pace.
            Speed(ladder_engine::runner::Speed),
            /// The scan engine online: native code, the interpreter, or both checked.
            ScanEngine(ladder_engine::vm::Engine),
            /// Apply saved scenario `0` (index in the project), or release it when applied.
            Scenario(usize),
        }

        impl Command {
            /// Every command without data, in menu order.
            pub const UNITS: &'static [Command] = &[$(Command::$name,)*];

            fn unit_text(self) -> Option<Msg> {
                match self {
                    $(Command::$name => Some(Msg::$msg),)*
                    _ => None,
                }
            }

            fn unit_shortcut(self) -> Option<KeyboardShortcut> {
                match self {
                    $(Command::$name => commands!(@key $($mods $key)?),)*
                    _ => None,
                }
            }
        }
    };
    (@key) => { None };
    (@key $mods:ident $key:ident) => { Some(KeyboardShortcut::new(Modifiers::$mods, Key::$key)) };
}

commands! {
    /// A new, empty project.
    New => New, COMMAND N;
    /// Pick a project and open it.
    Open => Open, COMMAND O;
    /// Save the project.
    Save => Save, COMMAND S;
    /// Save under a new name.
    SaveAs => SaveAs;
    /// Close the project.
    Close => Close;
    /// Export the instruction list.
    ExportIl => ExportIl;
    /// Export the comments as CSV.
    ExportComments => ExportComments;
    /// Import comments from CSV.
    ImportComments => ImportComments;
    /// The page setup of printing.
    PageSetup => PageSetup;
    /// The pages as they will print.
    PrintPreview => PrintPreview;
    /// Print: to the system's print queue, else to a PDF file.
    Print => Print, COMMAND P;
    /// Write the printed document as PDF or SVG pages.
    ExportDocument => ExportDocument;
    /// Quit.
    Exit => Exit, ALT F4;
    /// Take back the last change.
    Undo => Undo, COMMAND Z;
    /// Do the undone change again.
    Redo => Redo, COMMAND Y;
    /// Find an address, symbol, constant or instruction.
    Find => Find, COMMAND F;
    /// Replace an operand.
    Replace => Replace, COMMAND H;
    /// Go to a network and row (a row in a table).
    GoTo => GoTo, COMMAND G;
    /// A normally open contact at the cursor.
    Contact => ToolContact, NONE F1;
    /// A normally closed contact.
    ContactNc => ToolContactNc, SHIFT F1;
    /// A coil in the output column.
    Coil => ToolCoil, NONE F2;
    /// An inverted coil.
    CoilN => ToolCoilN, SHIFT F2;
    /// A function instruction (the dialog).
    Function => ToolFunction, NONE F3;
    /// A wire at the cursor.
    Wire => ToolWire, NONE F4;
    /// The vertical link left of the cursor, on or off.
    Link => ToolLink, NONE F5;
    /// A contact in parallel with the row above.
    Parallel => ToolParallel, NONE F6;
    /// A normally closed contact in parallel with the row above.
    ParallelNc => ToolParallelNc, SHIFT F6;
    /// Cut the selection.
    Cut => Cut, COMMAND X;
    /// Copy the selection.
    Copy => Copy, COMMAND C;
    /// Paste at the cursor.
    Paste => Paste, COMMAND V;
    /// Copy the cursor's row.
    CopyRow => CopyRow, COMMAND E;
    /// Delete the selection, else the element at the cursor.
    Delete => ToolDelete, NONE Delete;
    /// Delete the vertical link left of the cursor.
    DeleteLink => DeleteLink;
    /// A new row above the cursor.
    InsertRowAbove => InsertRowAbove, COMMAND T;
    /// A new row below the cursor.
    InsertRowBelow => InsertRowBelow, COMMAND R;
    /// Delete the cursor's row.
    DeleteRow => DeleteRow;
    /// A new network above the cursor's.
    InsertNetworkAbove => InsertNetworkAbove, COMMAND U;
    /// A new network below the cursor's.
    InsertNetworkBelow => InsertNetworkBelow, COMMAND I;
    /// Delete the cursor's network.
    DeleteNetwork => DeleteNetwork;
    /// Edit the network's title.
    NetworkTitle => NetworkTitle;
    /// Edit the network's comment.
    NetworkComment => NetworkComment;
    /// The symbol and comments of the element at the cursor, edited in place.
    Properties => ElementProperties, ALT Enter;
    /// Drop the selection.
    ClearSelection => ClearSelection, NONE Escape;
    /// Dragging draws wires and links (on/off).
    Pen => PenShort;
    /// Network comments shown (on/off).
    ToggleComments => ShowComments;
    /// Element comments under contacts and coils (on/off).
    ToggleElementComments => ShowElementComments, NONE F11;
    /// Rung coverage laid over the ladder (on/off; the first time, asks for the file).
    ToggleCoverage => ShowCoverage;
    /// Read a coverage file (`test --coverage`) and show it.
    LoadCoverage => CoverageFile;
    /// Network titles shown (on/off).
    ToggleTitles => ShowTitles;
    /// The project manager shown (on/off).
    ToggleTree => ProjectWindow;
    /// The output window shown (on/off).
    ToggleOutput => OutputWindow;
    /// The toolbars shown (on/off).
    ToggleToolbar => ToolbarView;
    /// The status bar shown (on/off).
    ToggleStatus => StatusBar;
    /// One zoom step up.
    ZoomIn => ZoomIn, COMMAND Plus;
    /// One zoom step down.
    ZoomOut => ZoomOut, COMMAND Minus;
    /// The zoom that fits the whole width, coils and boxes included, into the view (on/off).
    ZoomFit => ZoomFit, COMMAND Num0;
    /// Compile into the output window.
    Compile => Compile, NONE F9;
    /// The cursor to the next cell the last compile found wrong.
    NextError => NextError, NONE F12;
    /// The cursor to the previous cell the last compile found wrong.
    PreviousError => PreviousError, SHIFT F12;
    /// A new subprogram.
    NewSub => NewSub;
    /// Compile and run the PLC with the simulated CNC (online).
    Run => Run, COMMAND F9;
    /// Stop scanning; the machine keeps its state.
    Stop => StopRun, COMMAND F2;
    /// Run one 8 ms tick.
    StepTick => StepTick, NONE F8;
    /// Run N ticks (N in the online toolbar).
    StepN => StepN, SHIFT F8;
    /// Power off and on: PLC and CNC restart, retained data kept.
    PowerCycle => PowerCycle, ALT F8;
    /// Leave online mode: the machine is discarded.
    GoOffline => GoOffline;
    /// Write the opposite value to the bit at the cursor, once.
    ToggleBit => ToggleBit, NONE F7;
    /// Force the bit at the cursor to the opposite value, or release its force.
    ForceBit => ForceBit, SHIFT F7;
    /// Release the force of the element at the cursor.
    Unforce => Unforce, COMMAND F7;
    /// Release every force.
    UnforceAll => UnforceAll;
    /// Which contacts decide the output at the cursor, and when the deciding one last changed.
    Why => Why, ALT Y;
    /// Back from a recorded tick to the present.
    LiveView => LiveView;
    /// The online panel shown (on/off).
    ToggleOnline => OnlineWindow;
    /// The online panel in a native window of its own (a second screen holds it), on/off.
    DetachOnline => OnlineDetached;
    /// The Machine page: the machine model's devices, online or not.
    MachineModel => MachineModelPage;
    /// The page of saved scenarios.
    ScenariosPage => ScenariosPage;
    /// The cursor to the first column of its row.
    RowStart => CursorRowStart, NONE Home;
    /// The cursor to the output column of its row.
    RowEnd => CursorRowEnd, NONE End;
    /// The cursor a page of networks up.
    PageUp => CursorPageUp, NONE PageUp;
    /// The cursor a page of networks down.
    PageDown => CursorPageDown, NONE PageDown;
    /// The cursor to the block's first cell.
    BlockStart => CursorBlockStart, COMMAND Home;
    /// The cursor to the block's last row.
    BlockEnd => CursorBlockEnd, COMMAND End;
}

/// The PLC menu: compiling and the online commands (`None` is a separator).
pub const PLC_MENU: &[Option<Command>] = &[
    Some(Command::Compile),
    Some(Command::NextError),
    Some(Command::PreviousError),
    None,
    Some(Command::Run),
    Some(Command::Stop),
    Some(Command::StepTick),
    Some(Command::StepN),
    Some(Command::PowerCycle),
    Some(Command::GoOffline),
    None,
    Some(Command::ToggleBit),
    Some(Command::ForceBit),
    Some(Command::Unforce),
    Some(Command::UnforceAll),
    Some(Command::Why),
    Some(Command::LiveView),
    None,
    Some(Command::ToggleOnline),
    Some(Command::DetachOnline),
    Some(Command::MachineModel),
];

/// The online toolbar.
pub const ONLINE_TOOLBAR: &[Command] = &[
    Command::Run,
    Command::Stop,
    Command::StepTick,
    Command::StepN,
    Command::PowerCycle,
    Command::GoOffline,
];

/// The ladder editing commands in the groups the Edit and right-click menus show them.
pub const EDIT_GROUPS: [&[Command]; 3] = [
    &[
        Command::Contact,
        Command::ContactNc,
        Command::Coil,
        Command::CoilN,
        Command::Function,
        Command::Wire,
        Command::Link,
        Command::Parallel,
        Command::ParallelNc,
    ],
    &[
        Command::Cut,
        Command::Copy,
        Command::Paste,
        Command::CopyRow,
    ],
    &[
        Command::Delete,
        Command::DeleteLink,
        Command::InsertRowAbove,
        Command::InsertRowBelow,
        Command::DeleteRow,
        Command::InsertNetworkAbove,
        Command::InsertNetworkBelow,
        Command::DeleteNetwork,
        Command::NetworkTitle,
        Command::NetworkComment,
        Command::Properties,
    ],
];

/// The File menu, before the recent projects (`None` is a separator).
pub const FILE_MENU: &[Option<Command>] = &[
    Some(Command::New),
    Some(Command::Open),
    Some(Command::Save),
    Some(Command::SaveAs),
    Some(Command::Close),
    None,
    Some(Command::ExportIl),
    Some(Command::ExportComments),
    Some(Command::ImportComments),
    None,
    Some(Command::PageSetup),
    Some(Command::PrintPreview),
    Some(Command::Print),
    Some(Command::ExportDocument),
];

/// The View menu's switches.
pub const VIEW_TOGGLES: &[Command] = &[
    Command::ToggleTitles,
    Command::ToggleTree,
    Command::ToggleOutput,
    Command::ToggleToolbar,
    Command::ToggleStatus,
];

/// The basic toolbar (manual §3.3).
pub const BASIC_TOOLBAR: &[Command] = &[
    Command::New,
    Command::Open,
    Command::Save,
    Command::Cut,
    Command::Copy,
    Command::Paste,
    Command::Undo,
    Command::Redo,
    Command::GoTo,
    Command::Compile,
];

/// The ladder toolbar, after the pen switch (manual §3.3).
pub const LADDER_TOOLBAR: &[Command] = &[
    Command::Contact,
    Command::ContactNc,
    Command::Coil,
    Command::CoilN,
    Command::Function,
    Command::Wire,
    Command::Link,
    Command::Parallel,
    Command::Delete,
    Command::InsertRowBelow,
    Command::InsertNetworkBelow,
];

/// The display modes, in menu order.
pub const DISPLAY_MODES: [DisplayMode; 3] =
    [DisplayMode::Address, DisplayMode::Symbol, DisplayMode::Both];

/// The cross-reference views of the Tools menu.
pub const REFERENCE_VIEWS: [View; 3] = [View::RefIndex, View::RefBits, View::RefBytes];

/// The Help menu.
pub const HELP_PAGES: [HelpPage; 3] =
    [HelpPage::Shortcuts, HelpPage::Instructions, HelpPage::About];

const DIRS: [Dir; 4] = [Dir::Left, Dir::Right, Dir::Up, Dir::Down];

impl Command {
    /// Its name in menus and in the Help list.
    pub fn text(self) -> Msg {
        if let Some(m) = self.unit_text() {
            return m;
        }
        match self {
            Command::OpenRecent(_) => Msg::Open,
            Command::ViewCalls(_) => Msg::ViewCalls,
            Command::RenameSub(_) => Msg::RenameSub,
            Command::DeleteSub(_) => Msg::DeleteSub,
            Command::BlockInfo(_) => Msg::BlockInfo,
            Command::Language(Lang::Zh) => Msg::Chinese,
            Command::Language(Lang::En) => Msg::English,
            Command::Display(DisplayMode::Address) => Msg::DisplayAddress,
            Command::Display(DisplayMode::Symbol) => Msg::DisplaySymbol,
            Command::Display(DisplayMode::Both) => Msg::DisplayBoth,
            Command::ShowView(View::RefBits) => Msg::RefBits,
            Command::ShowView(View::RefBytes) => Msg::RefBytes,
            Command::ShowView(_) => Msg::RefIndex,
            Command::ShowCell(_) => Msg::GoTo,
            Command::ExportTraceCsv => Msg::TraceExport,
            Command::GoToRow(_) => Msg::GoTo,
            Command::ZoomTo(_) => Msg::ZoomLabel,
            Command::ConfirmForces(_) => Msg::ForceValue,
            Command::Help(HelpPage::Shortcuts) => Msg::Shortcuts,
            Command::Help(HelpPage::Instructions) => Msg::InstructionHelp,
            Command::Help(HelpPage::About) => Msg::About,
            Command::Move(Dir::Left) => Msg::CursorLeft,
            Command::Move(Dir::Right) => Msg::CursorRight,
            Command::Move(Dir::Up) => Msg::CursorUp,
            Command::Move(Dir::Down) => Msg::CursorDown,
            Command::Extend(Dir::Left) => Msg::ExtendLeft,
            Command::Extend(Dir::Right) => Msg::ExtendRight,
            Command::Extend(Dir::Up) => Msg::ExtendUp,
            Command::Extend(Dir::Down) => Msg::ExtendDown,
            Command::Speed(ladder_engine::runner::Speed::RealTime) => Msg::SpeedReal,
            Command::Speed(ladder_engine::runner::Speed::Times10) => Msg::Speed10,
            Command::Speed(ladder_engine::runner::Speed::Times100) => Msg::Speed100,
            Command::Speed(ladder_engine::runner::Speed::Max) => Msg::SpeedMax,
            Command::ScanEngine(ladder_engine::vm::Engine::Native) => Msg::EngineNative,
            Command::ScanEngine(ladder_engine::vm::Engine::Interpreter) => Msg::EngineInterp,
            Command::ScanEngine(ladder_engine::vm::Engine::Checked) => Msg::EngineChecked,
            Command::Scenario(_) => Msg::Scenarios,
            _ => Msg::Untitled,
        }
    }

    /// Its name on a toolbar button, where space is short.
    pub fn tool_text(self) -> Msg {
        match self {
            Command::InsertRowBelow => Msg::ToolRowBelow,
            Command::InsertNetworkBelow => Msg::ToolNetworkBelow,
            c => c.text(),
        }
    }

    /// The key that runs it, if any.
    pub fn shortcut(self) -> Option<KeyboardShortcut> {
        let arrow = |d: Dir| match d {
            Dir::Left => Key::ArrowLeft,
            Dir::Right => Key::ArrowRight,
            Dir::Up => Key::ArrowUp,
            Dir::Down => Key::ArrowDown,
        };
        match self {
            Command::Move(d) => Some(KeyboardShortcut::new(Modifiers::NONE, arrow(d))),
            Command::Extend(d) => Some(KeyboardShortcut::new(Modifiers::SHIFT, arrow(d))),
            c => c.unit_shortcut(),
        }
    }

    /// The shortcut as the menus and the Help list show it (`Ctrl+S`, `Shift+F1`).
    pub fn shortcut_text(self) -> Option<String> {
        self.shortcut()
            .map(|s| s.format(&ModifierNames::NAMES, cfg!(target_os = "macos")))
    }

    /// Whether its key acts even while a text field or a prompt has the keyboard: compiling
    /// and running never change what is being typed.
    pub fn global(self) -> bool {
        matches!(
            self,
            Command::Compile | Command::Run | Command::Stop | Command::StepTick | Command::StepN
        )
    }

    /// Every command that has a key, the most specific combination first (Shift+F1 before
    /// F1: egui matches a key without Shift also when Shift is held). Worked out once; the
    /// keys are looked up every frame.
    pub fn keyed() -> &'static [Command] {
        static KEYED: std::sync::LazyLock<Vec<Command>> = std::sync::LazyLock::new(|| {
            let mut all: Vec<Command> = Command::UNITS
                .iter()
                .copied()
                .chain(DIRS.iter().map(|d| Command::Extend(*d)))
                .chain(DIRS.iter().map(|d| Command::Move(*d)))
                .filter(|c| c.shortcut().is_some())
                .collect();
            let weight = |c: &Command| {
                let m = c.shortcut().map_or(Modifiers::NONE, |s| s.modifiers);
                std::cmp::Reverse(
                    u8::from(m.shift) + u8::from(m.alt) + u8::from(m.command || m.ctrl),
                )
            };
            all.sort_by_key(weight);
            all
        });
        &KEYED
    }

    /// Whether it changes the ladder at the cursor (refused outside a ladder view).
    pub fn edits_ladder(self) -> bool {
        EDIT_GROUPS.iter().any(|g| g.contains(&self)) || self.navigates()
    }

    /// Whether it only moves the cursor (allowed in a read-only replay too).
    pub fn navigates(self) -> bool {
        matches!(
            self,
            Command::Move(_)
                | Command::Extend(_)
                | Command::RowStart
                | Command::RowEnd
                | Command::PageUp
                | Command::PageDown
                | Command::BlockStart
                | Command::BlockEnd
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn no_two_commands_share_a_key_and_every_entry_has_a_text() {
        let keyed = Command::keyed();
        let mut seen = HashSet::new();
        for c in keyed {
            let s = c.shortcut().expect("keyed commands have a key");
            assert!(
                seen.insert((s.modifiers, s.logical_key)),
                "{c:?} shares {s:?}"
            );
            assert_ne!(c.text(), Msg::Untitled, "{c:?}");
        }
        for c in Command::UNITS {
            assert_ne!(c.text(), Msg::Untitled, "{c:?}");
        }
        // Shift+F1 must be tried before F1, or a normally closed contact can never be typed.
        let pos = |c| keyed.iter().position(|k| *k == c).unwrap();
        assert!(pos(Command::ContactNc) < pos(Command::Contact));
        assert!(pos(Command::Extend(Dir::Left)) < pos(Command::Move(Dir::Left)));
    }

    #[test]
    fn shortcuts_read_as_the_manual_writes_them() {
        assert_eq!(Command::Save.shortcut_text().as_deref(), Some("Ctrl+S"));
        assert_eq!(
            Command::ContactNc.shortcut_text().as_deref(),
            Some("Shift+F1")
        );
        assert_eq!(Command::Delete.shortcut_text().as_deref(), Some("Delete"));
        assert_eq!(Command::DeleteRow.shortcut_text(), None);
    }
}
