//! The user interface's two languages. Every text the UI shows is a [`Msg`]; `text` gives it
//! in Chinese or English, so a missing translation is a compile error, not a blank label.

use serde::{Deserialize, Serialize};

/// A UI language.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Lang {
    /// 中文.
    #[default]
    Zh,
    /// English.
    En,
}

impl Lang {
    /// The language a user of this system most likely reads: Chinese when the locale says so.
    pub fn from_locale(locale: Option<&str>) -> Lang {
        match locale {
            Some(l) if l.to_ascii_lowercase().starts_with("zh") => Lang::Zh,
            Some(_) => Lang::En,
            None => Lang::Zh,
        }
    }

    /// The code used for per-language comments (`zh`, `en`).
    pub fn code(self) -> &'static str {
        match self {
            Lang::Zh => "zh",
            Lang::En => "en",
        }
    }
}

macro_rules! messages {
    ($($name:ident => $zh:literal, $en:literal;)*) => {
        /// Every text of the user interface.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        #[allow(missing_docs)] // The variant names say what the text is.
        pub enum Msg { $($name,)* }

        impl Msg {
            /// Every message, for the translation test.
            pub const ALL: &'static [Msg] = &[$(Msg::$name,)*];

            /// The text in a language.
            pub fn text(self, lang: Lang) -> &'static str {
                match (self, lang) {
                    $((Msg::$name, Lang::Zh) => $zh, (Msg::$name, Lang::En) => $en,)*
                }
            }
        }
    };
}

messages! {
    File => "文件", "File";
    Edit => "编辑", "Edit";
    View => "查看", "View";
    Plc => "PLC", "PLC";
    // Online: run control, live ladder, watch table, forces, alarms, recorder.
    Run => "运行（在线）", "Run (online)";
    StopRun => "停止运行", "Stop";
    StepTick => "单步（1 个 8 ms 周期）", "Single tick (8 ms)";
    StepN => "运行 N 个周期", "Step N ticks";
    PowerCycle => "重新上电（PLC 与 CNC）", "Power cycle (PLC and CNC)";
    GoOffline => "脱机", "Go offline";
    ToggleBit => "取反光标处的位（写一次）", "Toggle the bit at the cursor (write once)";
    ForceBit => "强制/解除光标处的位", "Force / release the bit at the cursor";
    Unforce => "解除光标处的强制", "Release the force at the cursor";
    UnforceAll => "解除全部强制", "Release all forces";
    Why => "为什么？", "Why?";
    LiveView => "回到实时", "Back to live";
    OnlineWindow => "在线窗口", "Online window";
    OnlineDetached => "在线窗口独立显示", "Online window on its own";
    MachineModelPage => "机床模型…", "Machine model…";
    SpeedReal => "实时", "Real time";
    Speed10 => "×10", "×10";
    Speed100 => "×100", "×100";
    SpeedMax => "最快", "As fast as possible";
    SpeedLabel => "速度", "Speed";
    LiveFormat => "数值格式", "Format";
    ValuesTitle => "在线数值", "live values";
    StepNHint => "“运行 N 个周期”（Shift+F8）的周期数", "Ticks of \"Step N ticks\" (Shift+F8)";
    Ticks => "周期", "ticks";
    StateRunning => "运行中", "running";
    StateStopped => "已停止", "stopped";
    PlcHalted => "PLC 停止", "PLC halted";
    OnlineStarted => "在线：PLC 与仿真 CNC 已就绪（Ctrl+F9 运行，F8 单步）", "Online: the PLC and the simulated CNC are ready (Ctrl+F9 runs, F8 steps)";
    RunNeedsCompile => "有编译错误，不能运行：先改正输出窗口中的错误", "The program has compile errors and cannot run: fix the errors in the output window first";
    RunFailed => "不能启动机床", "Cannot start the machine";
    MachineRefused => "机床未执行", "The machine refused";
    MachineFailed => "机床线程出错并已停止", "The machine thread failed and stopped";
    EditSwapped => "修改已在线生效（在周期之间切换，存储器保持）", "The edit runs now (swapped between two ticks, memory kept)";
    KeptInstances => "保持状态的功能指令", "function instances kept";
    FreshInstances => "新指令", "new";
    EditNotSwapped => "修改未能在线生效", "The edit could not take over";
    EditNotCompiled => "修改有编译错误，未在线生效：运行的仍是原程序", "The edit does not compile and was not swapped in: the machine still runs the previous program";
    DrawingRuns => "运行程序 = 梯形图", "Running program = drawing";
    DrawingSwapping => "正在切换到修改后的程序", "Swapping in the edited program";
    DrawingDiffers => "运行程序 ≠ 梯形图", "Running program ≠ drawing";
    ShowingPast => "回放（只读）", "Replay (read-only)";
    Timeline => "扫描记录", "Scan record";
    RecorderEmpty => "扫描记录：尚无记录（运行或单步后开始）", "Scan record: empty (it starts with the first tick)";
    TabPanel => "操作面板", "Panel";
    TabCnc => "CNC", "CNC";
    TabWatch => "监视表", "Watch";
    TabForces => "强制", "Forces";
    TabSignals => "PLC 信号", "PLC signals";
    SignalArea => "地址区", "Area";
    SignalFrom => "从", "from";
    SignalTo => "到", "to";
    SignalClickForces => "单击强制/解除", "A click forces or releases";
    SignalHint => "单击某位写入相反值一次（勾选上面的选项则强制或解除）；右键菜单两者都有；整字节或数值在右侧输入后写入或强制。悬停显示符号和注释。", "A click on a bit writes its opposite once (or forces and releases, with the box above ticked); its right-click menu has both; a whole byte or value is typed on the right, then written or forced. Hover for the symbol and comment.";
    TabTrace => "信号跟踪", "Trace";
    TabAlarms => "报警", "Alarms";
    TabMachine => "机床", "Machine";
    MachineEmpty => "本工程没有机床模型：添加设备，让梯形图的输出得到机床的回应（刀架、卡盘、挡块……）。", "This project has no machine model: add devices so that the ladder's outputs get the machine's answers (turret, chuck, dogs, …).";
    MachineAdd => "添加设备", "Add device";
    MachineName => "名称", "Name";
    MachineKind => "类型", "Kind";
    MachineInputs => "写入的输入", "Inputs written";
    MachineState => "状态", "State";
    MachineEdit => "编辑", "Edit";
    MachineDelete => "删除", "Delete";
    MachineFault => "故障", "Fault";
    MachineDevice => "设备", "Device";
    MachineOptional => "（可不填）", "(optional)";
    MachineApply => "应用", "Apply";
    MachineStartBad => "上电位置应为 −100000…100000 mm 的数", "A power-on position is a number of mm, −100000…100000";
    MachineChanged => "设备已被修改（撤销或其他编辑）：请关闭表单后重新编辑", "The device changed under the form (an undo or another edit): cancel and edit it again";
    MachineStart => "上电时各轴位置（mm，距参考点）：", "Axes at power-on (mm from the reference point):";
    DeviceFaults => "设备故障", "Device faults";
    ForcedCount => "强制生效", "Forces active";
    FirstForceTitle => "强制信号", "Force a signal";
    FirstForceQuestion => "强制会使信号保持指定值，不论程序和机床如何动作，直到解除强制。在真实机床上这可能使设备意外动作。确定要强制吗？（本次运行中不再询问）", "A force holds a signal at its value whatever the program and the machine do, until released. On a real machine this can move things unexpectedly. Force it? (Not asked again while the editor runs.)";
    ScanSteps => "扫描", "Scan";
    ScanHint => "每个扫描周期执行的步数：上一周期 / 上电以来最大 / 看门狗上限（一级程序每周期、二级程序每轮超过此步数即停止 PLC）", "Steps executed per tick: the last tick / the most since power-on / the watchdog's limit (a level stops the PLC past it: level 1 per tick, level 2 per cycle)";
    OfflineHint => "脱机：Ctrl+F9 运行或 F8 单步后显示在线状态", "Offline: Ctrl+F9 (run) or F8 (single tick) shows the live state";
    NoForces => "没有强制", "Nothing is forced";
    Release => "解除", "Release";
    ReleaseAll => "全部解除", "Release all";
    Forced => "强制", "forced";
    NoBitAtCursor => "光标处不是位元件（触点或线圈）", "The cursor is not on a bit element (a contact or coil)";
    PlcAlarms => "PLC 报警与操作信息", "PLC alarms and operator messages";
    NoAlarms => "无", "None";
    WatchHint => "地址或符号，如 X0002.3、D0010:2、KEY_JOG", "Address or symbol, e.g. X0002.3, D0010:2, KEY_JOG";
    WatchAdd => "添加", "Add";
    WatchAddress => "地址/符号", "Address/symbol";
    WatchFormat => "格式", "Format";
    WatchSymbol => "符号/注释", "Symbol/comment";
    DataRunning => "运行中的值（在线）", "Running values (online)";
    DataSaveRunning => "将运行中的值存入工程", "Save running values into the project";
    DataDiffer => "行的运行值与工程文件不同", "rows differ from the project file";
    DataAddress => "地址", "Address";
    DataFile => "工程文件", "Project file";
    DataRunningValue => "运行中", "Running";
    DataBadValue => "不是此表可用的数值", "is not a value this table takes";
    WatchWriteAll => "写入全部预备值", "Write prepared values";
    WatchForceAll => "强制全部预备值", "Force prepared values";
    WatchPrepared => "行有预备值（新值列），在同一扫描周期内一并写入或强制", "rows have a prepared value (the New value column), written or forced together in one tick";
    WatchValue => "当前值", "Value";
    WatchNew => "新值", "New value";
    WatchTraced => "跟踪", "Trace";
    WatchRemove => "删除此行", "Remove this row";
    WriteOnce => "写入", "Write";
    ForceValue => "强制", "Force";
    WhyNeedsOutput => "“为什么？”需要光标在运行中的线圈或功能指令所在行", "\"Why?\" needs the cursor on the row of a coil or function box of the running program";
    HoldsIt => "使其接通", "holds it on";
    BrokeIt => "使其断开", "broke the rung";
    LastChangedAt => "最后变化于周期", "last changed at tick";
    NotChangedInRecord => "记录中未变化", "unchanged in the record";
    NoDecidingContact => "无触点决定（直接接在母线上）", "no contact decides it (wired to the rail)";
    Tools => "工具", "Tools";
    Help => "帮助", "Help";
    Open => "打开…", "Open…";
    Save => "保存", "Save";
    Exit => "退出", "Exit";
    Recent => "最近打开的文件", "Recent files";
    Compile => "编译", "Compile";
    NextError => "下一个错误", "Next error";
    MoreTools => "更多工具", "More tools";
    Printer => "打印机", "Printer";
    NoPrinters => "（打印系统未列出打印机）", "(the print system lists no printer)";
    DefaultPrinter => "默认", "default";
    PrintNetworks => "网络范围", "Networks";
    ElementProperties => "元件属性", "Element properties";
    SymbolLabel => "符号", "Symbol";
    CommentLabel => "注释", "Comment";
    PropertiesHint => "写入符号表（可撤销）；注释最多显示三行", "Written into the symbol table (undoable); up to three comment lines are shown";
    PropertiesNoAddress => "光标处不是带地址的触点或线圈", "The cursor is not on a contact or coil with an address";
    PreviousError => "上一个错误", "Previous error";
    NoMarks => "上次编译没有指向梯形图单元的错误或警告", "The last compile found no error or warning in a ladder cell";
    ErrorsInDiagram => "错误", "errors";
    WarningsInDiagram => "警告", "warnings";
    Language => "语言", "Language";
    Chinese => "中文", "中文 (Chinese)";
    English => "English (英文)", "English";
    ZoomIn => "放大", "Zoom in";
    ZoomOut => "缩小", "Zoom out";
    ZoomFit => "适合宽度", "Fit width";
    DisplayAddress => "地址显示", "Show addresses";
    DisplaySymbol => "符号显示", "Show symbols";
    DisplayBoth => "地址：符号显示", "Show address: symbol";
    ShowComments => "显示网络注释", "Show network comments";
    ShowElementComments => "显示元件注释", "Show element comments";
    ShowCoverage => "显示覆盖率", "Show coverage";
    ScanEngine => "扫描引擎", "Scan engine";
    EngineNative => "本机代码（最快）", "Native code (fastest)";
    EngineInterp => "解释器（参照）", "Interpreter (reference)";
    EngineChecked => "两者对照检查", "Both, checked against each other";
    CoverageFile => "打开覆盖率文件…", "Coverage file…";
    Coverage => "覆盖率", "Coverage";
    CoverFull => "已覆盖", "covered";
    CoverHalf => "部分覆盖", "half";
    CoverNever => "未运行", "never";
    CoverageOpenNetworks => "个网络未完全覆盖（单击转到）", "networks not fully covered (click to go there)";
    CoverageLeft => "待覆盖", "left";
    CoverageUnread => "无法读取覆盖率文件", "Cannot read the coverage file";
    CoverageLive => "（运行中测量）", "(measured on the running machine)";
    About => "关于 Ladder Studio", "About Ladder Studio";
    Project => "工程", "Project";
    Ladder => "梯形图", "Ladder";
    Level1 => "一级程序", "Level 1";
    Level2 => "二级程序", "Level 2";
    Subprograms => "子程序", "Subprograms";
    SymbolTables => "符号表", "Symbol tables";
    DataTables => "数据设置表", "Data-setting tables";
    Messages => "显示信息表", "Display messages";
    Reference => "引用索引表", "Cross-reference";
    RefIndex => "索引", "Index";
    RefBits => "位使用", "Bit usage";
    RefBytes => "字节使用", "Byte usage";
    Diagnosis => "诊断信息表", "Diagnosis";
    Permissions => "权限表", "Permissions";
    MCodes => "M 代码注释表", "M-code comments";
    VersionInfo => "梯形图版本信息", "Version information";
    Scenarios => "场景", "Scenarios";
    ScenariosPage => "编辑场景…", "Edit scenarios…";
    ScenarioNone => "工程中还没有场景", "The project has no scenarios yet";
    ScenarioNew => "新建场景", "New scenario";
    ScenarioDelete => "删除场景", "Delete scenario";
    ScenarioName => "名称", "Name";
    ScenarioNote => "说明", "Note";
    ScenarioLines => "内容（每行一条）", "Lines (one per line)";
    ScenarioHelp => "每行一条：set 地址 值 · force 地址 值 · panel \"面板标签\" 状态 · device 设备名 fault …；应用后在“PLC”菜单或本页解除即恢复原状", "One per line: set ADDR VALUE · force ADDR VALUE · panel \"LABEL\" STATE · device NAME fault …; releasing it (PLC menu or this page) puts back what it changed";
    ScenarioApply => "应用", "Apply";
    ScenarioRelease => "解除", "Release";
    ScenarioApplied => "已应用", "applied";
    ScenarioNowApplied => "应用场景", "Apply scenario";
    ScenarioRenameApplied => "请先解除该场景再改名（它以此名称应用）", "Release the scenario before renaming it (it is applied by this name)";
    ScenarioNowReleased => "解除场景", "Release scenario";
    ScenarioOk => "每一行都可以应用", "Every line can be applied";
    Output => "信息输出", "Output";
    CopyLine => "复制这一行", "Copy this line";
    CopyAll => "全部复制", "Copy all";
    Network => "网络", "Network";
    Steps => "步数", "Steps";
    StepsUnit => "步", "steps";
    NoProject => "没有打开的工程", "No project open";
    Modified => "已修改", "modified";
    Untitled => "未命名", "untitled";
    Errors => "错误", "errors";
    Warnings => "警告", "warnings";
    OpenFailed => "无法打开", "Cannot open";
    CompileClean => "编译完成，没有错误", "Compiled without errors";
    Operand => "参数", "Operand";
    Found => "处找到", "found";
    GoToUsage => "转到：输入“网络号 [行号]”，例如 12 3", "Go to: type `NETWORK [ROW]`, e.g. 12 3";
    NoSuchNetwork => "没有这个网络", "No such network";
    NoSuchRow => "这个网络没有这一行", "No such row in this network";
    ToolContact => "常开触点", "NO contact";
    ToolContactNc => "常闭触点", "NC contact";
    ToolCoil => "线圈", "Coil";
    ToolCoilN => "取反线圈", "Inverted coil";
    ToolFunction => "功能指令", "Function";
    ToolWire => "横线", "Wire";
    ToolLink => "竖线", "Vertical link";
    ToolParallel => "并联触点", "Parallel contact";
    ToolParallelNc => "并联常闭触点", "Parallel NC contact";
    ClearSelection => "取消选择", "Clear selection";
    CursorLeft => "光标左移", "Cursor left";
    CursorRowStart => "光标到行首", "Cursor to the row's start";
    CursorRowEnd => "光标到行尾（输出列）", "Cursor to the row's end (output column)";
    CursorPageUp => "光标上翻一页", "Cursor a page up";
    CursorPageDown => "光标下翻一页", "Cursor a page down";
    CursorBlockStart => "光标到程序开头", "Cursor to the block's start";
    CursorBlockEnd => "光标到程序末尾", "Cursor to the block's end";
    CursorRight => "光标右移", "Cursor right";
    CursorUp => "光标上移", "Cursor up";
    CursorDown => "光标下移", "Cursor down";
    ExtendLeft => "向左扩展选择", "Extend selection left";
    ExtendRight => "向右扩展选择", "Extend selection right";
    ExtendUp => "向上扩展选择", "Extend selection up";
    ExtendDown => "向下扩展选择", "Extend selection down";
    ToolDelete => "删除", "Delete";
    ToolRowBelow => "插入行", "Insert row";
    ToolNetworkBelow => "插入网络", "Insert network";
    Replaced => "处已替换", "replaced";
    SkippedInvalid => "处因结果无效未替换", "skipped where the result would be invalid";
    NothingToFind => "不是地址、符号、常数或指令", "is not an address, symbol, constant or instruction";
    FindPrompt => "查找（地址、符号、常数或指令）：", "Find (an address, symbol, constant or instruction):";
    GoToPrompt => "转到网络 [行]：", "Go to network [row]:";
    GoToRowPrompt => "转到表格行：", "Go to table row:";
    ReplaceTitle => "替换", "Replace";
    ReplaceFrom => "查找（地址、符号、常数或指令）", "Find (an address, symbol, constant or instruction)";
    ReplaceTo => "替换为（操作数）", "Replace with (an operand)";
    ReplaceOne => "替换选中的一处", "Replace the selected one";
    ReplaceAll => "全部替换", "Replace all";
    ReplaceClose => "关闭", "Close";
    ReplacePlaces => "处", "places";
    ReplaceWillChange => "处将替换", "to change";
    ReplaceSkipped => "处跳过（结果在此无效）", "skipped (the result is not valid there)";
    ReplaceNone => "没有找到", "Nothing found";
    ReplaceUsage => "替换：输入“原地址 新地址”，例如 R10.0 R11.0", "Replace: type `FROM TO`, e.g. R10.0 R11.0";
    SaveNeedsName => "工程还没有文件名：请先另存为", "The project has no file name yet: use Save As";
    // Files and menus.
    Cut => "剪切", "Cut";
    Copy => "复制", "Copy";
    Paste => "粘贴", "Paste";
    CopyRow => "复制一行", "Copy row";
    DeleteLink => "删除竖线", "Delete vertical link";
    InsertRowAbove => "插入行（上）", "Insert row above";
    InsertRowBelow => "插入行（下）", "Insert row below";
    DeleteRow => "删除行", "Delete row";
    InsertNetworkAbove => "插入网络（上）", "Insert network above";
    InsertNetworkBelow => "插入网络（下）", "Insert network below";
    DeleteNetwork => "删除当前网络", "Delete network";
    NetworkTitle => "网络标题…", "Network title…";
    NetworkComment => "网络注释…", "Network comment…";
    CallsFound => "处调用", "calls";
    SubExists => "子程序已存在", "this subprogram already exists";
    SubUsage => "输入“子程序号 [名称]”，例如 12 TOOL_CHANGE，范围", "Type `NUMBER [NAME]`, e.g. 12 TOOL_CHANGE, range";
    BadSymbolName => "不是合法的符号名（字母、数字、下划线、汉字，不以数字开头）", "is not a valid symbol name (letters, digits, underscores, CJK; not starting with a digit)";
    ClipboardEmpty => "剪贴板是空的：先复制或剪切", "The clipboard is empty: copy or cut first";
    NewSub => "新建子程序…", "New subprogram…";
    RenameSub => "重命名子程序…", "Rename subprogram…";
    DeleteSub => "删除子程序", "Delete subprogram";
    BlockInfo => "程序块信息…", "Block information…";
    ViewCalls => "查看调用", "View calls";
    Undo => "撤消", "Undo";
    Redo => "重做", "Redo";
    Find => "查找…", "Find…";
    Replace => "替换…", "Replace…";
    GoTo => "转到…", "Go to…";
    DisplayModeLabel => "显示地址类型", "Operands";
    ZoomLabel => "缩放比例", "Zoom";
    Suggestions => "符号（Tab 选第一个）：", "Symbols (Tab takes the first):";
    XrefFilter => "地址或符号", "Address or symbol";
    XrefHint => "双击一行跳转到该元件", "Double-click a row to go to the element";
    XrefUse => "读/写", "Use";
    XrefBlock => "程序块", "Block";
    XrefPlace => "位置", "Place";
    XrefElement => "元件", "Element";
    Tab => "标签", "Tab";
    NoSuchTableRow => "表格没有这一行", "The table has no such row";
    GoToRowUsage => "转到：输入表格的行号，例如 25", "Go to: type a row number of the table, e.g. 25";
    NoSuchSub => "这个程序块已不存在", "this block no longer exists";
    PenShort => "画线", "Draw lines";
    SaveChanges => "保存修改", "Save changes";
    Pen => "画线模式（拖动画横线/竖线）", "Line mode (drag to draw wires and links)";
    Shortcuts => "快捷键", "Keyboard shortcuts";
    InstructionHelp => "指令说明", "Instruction reference";
    AboutText => "GSK 数控系统 PLC 梯形图编辑与仿真工具。", "Ladder editor and simulator for the PLC of GSK CNC controllers.";
    ToolbarView => "显示工具栏", "Show toolbars";
    OutputWindow => "显示信息输出窗", "Show output window";
    ProjectWindow => "显示工程管理器", "Show project manager";
    StatusBar => "显示状态栏", "Show status bar";
    ShowTitles => "显示网络标题", "Show network titles";
    Cursor => "光标", "Cursor";
    Row => "行", "Row";
    Column => "列", "Column";
    ModeEdit => "编辑", "Edit";
    ModeReadOnly => "只读", "Read-only";
    Selected => "已选择", "selected";
    BlockInfoPrompt => "程序块信息", "Block information";
    TitlePrompt => "网络标题", "Network title";
    CommentPrompt => "网络注释", "Network comment";
    SubPrompt => "子程序号 名称", "Number name";
    New => "新建", "New";
    SaveAs => "另存为…", "Save As…";
    Close => "关闭", "Close";
    ExportIl => "导出指令表…", "Export instruction list…";
    PageSetup => "页面设置…", "Page setup…";
    PrintPreview => "打印预览", "Print preview";
    Print => "打印…", "Print…";
    ExportDocument => "导出为 PDF/SVG…", "Export as PDF/SVG…";
    NoPrintQueue => "本系统没有打印队列（lp）：请选择 PDF 的保存位置", "This system has no print queue (lp): choose where to save the PDF";
    SentToPrinter => "已发送到打印队列", "Sent to the print queue";
    PrintFailed => "打印失败", "Printing failed";
    Pages => "页", "pages";
    PreviousPage => "上一页", "Previous page";
    NextPage => "下一页", "Next page";
    Paper => "纸张", "Paper";
    Orientation => "方向", "Orientation";
    Portrait => "纵向", "Portrait";
    Landscape => "横向", "Landscape";
    BothLanguages => "中英文对照", "Chinese and English";
    ElementComments => "元件注释", "Element comments";
    PrintTables => "打印符号表、数据表和信息显示表", "Print the symbol, data and message tables";
    PrintXref => "打印交叉引用表", "Print the cross-reference";
    SelectionOnly => "仅打印所选网络", "Selected networks only";
    ExportComments => "导出注释…", "Export comments…";
    ImportComments => "导入注释…", "Import comments…";
    OpenedReadOnly => "已只读打开损坏文件中可读的部分（只能另存为）", "Opened what could be read of the damaged file, read-only (use Save As)";
    CannotRecover => "无法恢复", "Cannot recover";
    ReadOnlySaveAs => "只读工程：请另存为新文件", "Read-only project: save it under a new name";
    NotOverDamaged => "不能覆盖损坏的原文件：请选择另一个文件名", "The damaged original is not overwritten: choose another name";
    IlNotWritten => "有网络无法生成指令表：请先修正编译错误，指令表未写出", "A network has no valid instruction list: fix the compile errors; nothing written";
    Written => "已写出", "Written:";
    ReadOnly => "只读工程，不能修改", "The project is read-only";
    Replaying => "正在回放记录：不能修改，请先回到实时", "A recording is replayed: nothing can change until Back to live";
    RowsApplied => "行注释已导入", "comment rows applied";
    AutosaveFailed => "自动保存恢复副本失败", "Autosave of the recovery copy failed";
    Restored => "已从恢复副本恢复工程（尚未保存）", "Project restored from its recovery copy (not saved yet)";
    UnsavedTitle => "未保存的修改", "Unsaved changes";
    SaveChangesTo => "是否保存对以下工程的修改", "Save the changes to";
    DontSave => "不保存", "Don't save";
    Cancel => "取消", "Cancel";
    DamagedTitle => "文件已损坏", "Damaged file";
    // The in-app file dialog (when the system's cannot appear).
    DialogOpen => "打开", "Open";
    DialogSave => "保存", "Save";
    NewFolder => "新建文件夹", "New folder";
    NewFolderName => "新文件夹", "New folder";
    Refresh => "刷新", "Refresh";
    ParentFolder => "上一级文件夹", "Parent folder";
    FileLabel => "文件名：", "File name:";
    ShowHidden => "显示隐藏文件", "Show hidden files";
    OpenReadOnlyQuestion => "是否只读打开其中可读的部分？", "Open what can be read of it, read-only?";
    OpenReadOnly => "只读打开", "Open read-only";
    RestoreTitle => "恢复工程", "Recover project";
    RestoreQuestion => "上次编辑没有正常结束，找到了自动保存的恢复副本：", "The last session did not end normally. An autosaved recovery copy was found:";
    MinutesAgo => "分钟前", "minutes ago";
    Restore => "恢复", "Restore";
    Discard => "丢弃", "Discard";
    // Table editors.
    TblRow => "行", "Row";
    TblAddress => "地址", "Address";
    TblSymbol => "符号", "Symbol";
    TblComment => "注释", "Comment";
    TblValue => "初始值", "Initial value";
    TblMin => "最小值", "Min";
    TblMax => "最大值", "Max";
    TblAlarmNumber => "报警号", "Alarm number";
    TblMessageText => "显示内容", "Message text";
    TblMCode => "M 代码", "M code";
    TblHex => "十六进制", "Hex";
    TblProblem => "错误", "Problem";
    TblClear => "清除", "Clear row";
    TblInsertAbove => "在上方插入", "Insert row above";
    TblInsertBelow => "在下方插入", "Insert row below";
    TblDelete => "删除", "Delete row";
    TblSelectRowFirst => "请先选择一行", "Select a row first";
    TblFixedRows => "显示信息表每个 A 位固定一行，不能插入或删除行", "The message table has one fixed row per A bit: rows cannot be inserted or deleted";
    TblNewRowAddress => "输入地址以添加一行", "Type an address to add a row";
    TblNewRowCode => "输入 M 代码以添加一行", "Type an M code to add a row";
    TblNoSuchTable => "没有这个符号表", "No such symbol table";
    TblKPage => "K 值设置", "K settings";
    TblTabD => "D", "D";
    TblTabDFloat => "D_FLOAT", "D_FLOAT";
    TblTabDt => "DT", "DT";
    TblTabDc => "DC", "DC";
    TblErrSyntax => "不是地址（例如 X0002.1、R100、D4、DT0004）", "is not an address (e.g. X0002.1, R100, D4, DT0004)";
    TblErrArea => "没有这种地址类型", "has no such address area";
    TblErrBit => "位号必须是 0–7", "the bit must be 0–7";
    TblErrNoBits => "这种地址没有位", "this area has no bit addresses";
    TblErrRange => "超出范围", "is out of range";
    TblErrAreaHere => "这里只能用这些地址：", "only these areas belong here:";
    TblErrAddressEmpty => "地址不能为空（删除这一行请用“删除”）", "An address is required (use Delete row to remove the row)";
    TblErrAddressTwice => "地址已存在：", "address already listed:";
    TblErrSymbolName => "符号只能由字母、数字、下划线和汉字组成，首字符不能是数字，不超过 32 个字符，且不能是地址", "A symbol is letters, digits, `_` and Chinese characters, does not start with a digit, has at most 32 characters and is not an address";
    TblErrSymbolTwice => "符号已存在：", "symbol already exists:";
    TblErrSymbolElsewhere => "该符号已代表", "this symbol already stands for";
    TblErrCommentLong => "注释不能超过 127 字节", "A comment has at most 127 bytes";
    TblErrInteger => "请输入 -2147483647 到 2147483647 之间的整数", "Enter a whole number from -2147483647 to 2147483647";
    TblErrReal => "请输入一个数", "Enter a number";
    TblErrAlarmRange => "报警号的范围是 1000–9999", "Alarm numbers are 1000–9999";
    TblErrAlarmTwice => "报警号已被使用：", "alarm number already used by";
    TblErrMCode => "M 代码的范围是 0–9999", "M codes are 0–9999";
    TblErrMCodeTwice => "M 代码已存在", "This M code is already listed";
    TblErrNoFree => "没有可插入的空闲地址", "No free address left to insert";
    TblProjectName => "工程名称", "Project name";
    TblDesigner => "梯形图设计", "Designer";
    TblVersion => "梯形图版本", "Version";
    TblRemarks => "备注", "Remarks";
    TblPassword => "梯形图密码", "Ladder password";
    TblPasswordIsSet => "已设置密码", "A password is set";
    TblPasswordNone => "未设置密码", "No password set";
    TblPasswordCurrent => "当前密码", "Current password";
    TblPasswordNew => "新密码", "New password";
    TblPasswordConfirm => "确认密码", "Confirm password";
    TblSetPassword => "设置密码", "Set password";
    TblClearPassword => "清除密码", "Clear password";
    TblPasswordMismatch => "两次输入的密码不一致", "The two passwords differ";
    TblPasswordWrong => "当前密码不正确", "The current password is wrong";
    TblPasswordEmpty => "密码不能为空", "The password is empty";
    TblPasswordSaved => "密码已设置（只保存加盐哈希）", "Password set (only a salted hash is stored)";
    TblPasswordCleared => "密码已清除", "Password cleared";
    // Function-instruction dialog.
    FnTitle => "功能指令", "Function instruction";
    FnEditTitle => "修改功能指令", "Change function instruction";
    FnLine => "指令行", "Instruction line";
    FnSearch => "搜索", "Search";
    FnCategory => "分类", "Category";
    FnAll => "所有功能指令", "All";
    FnNoMatch => "没有匹配的功能指令", "No function instruction matches";
    FnChoose => "请选择一个功能指令", "Choose a function instruction";
    FnParameter => "参数", "Parameter";
    FnValue => "值", "Value";
    FnNote => "注释", "Description";
    FnMissing => "未填写", "missing";
    FnNotAllowed => "此处不允许", "not allowed here";
    FnAllowedAreas => "允许的地址区", "allowed areas";
    FnAllowedConsts => "允许的常数", "allowed constants";
    FnRealConsts => "实数常数", "real constants";
    FnNoConsts => "不接受常数", "no constants";
    FnWantsBit => "需要位地址，例如 R0010.0", "needs a bit address such as R0010.0";
    FnWantsByte => "需要不带位号的地址，例如 R0010", "needs an address without a bit, such as R0010";
    FnReadOnly => "X、F 是输入信号，程序不能写", "X and F are inputs: the program cannot write them";
    FnOutOfRange => "超出本机型的地址范围", "beyond the address range of this controller";
    FnUndefinedSymbol => "符号未定义：请在符号表中定义或直接写地址", "undefined symbol: define it in the symbol table or write the address";
    FnNotFunction => "不是功能指令", "is not a function instruction";
    FnTooMany => "参数过多", "too many operands";
    FnTable => "转换表", "Conversion table";
    FnEntries => "项", "entries";
    FnAddEntry => "添加表项", "Add entry";
    FnRemoveEntry => "删除表项", "Remove entry";
    FnIl => "指令表", "IL";
    FnOk => "确定", "OK";
    FnCancel => "取消", "Cancel";
    // Online: operator panel, CNC panel, signal trace
    PanelEdit => "编辑面板", "Edit panel";
    PanelDone => "完成编辑", "Done editing";
    PanelEditHint => "单击一项进行修改，或添加新项", "Click an item to change it, or add one";
    PanelAdd => "添加项", "Add item";
    PanelRemove => "删除此项", "Remove item";
    PanelApply => "应用", "Apply";
    PanelCancel => "取消", "Cancel";
    PanelReset => "恢复预设面板（GSK988TA）", "Reset to the preset (GSK988TA)";
    PanelLabelZh => "中文标签", "Chinese label";
    PanelLabelEn => "英文标签", "English label";
    PanelKindLabel => "类型", "Kind";
    PanelKey => "按键（按住为 1）", "Key (1 while held)";
    PanelSwitch => "开关（每按一次切换）", "Switch (toggles)";
    PanelLampKey => "带灯按键", "Key with lamp";
    PanelLamp => "指示灯", "Lamp";
    PanelKnob => "波段开关", "Knob";
    PanelInput => "输入地址", "Input address";
    PanelLampAddress => "指示灯地址", "Lamp address";
    PanelPositions => "档位（名称=值; 名称=值 …）", "Positions (name=value; name=value …)";
    PanelRow => "行", "Row";
    PanelCol => "列", "Column";
    PanelNoPosition => "（不在档位上）", "(between positions)";
    PanelBadPositions => "档位写法为 名称=值，以分号分隔，值为 0–255 的整数", "write the positions as name=value separated by semicolons, values 0–255";
    PanelItemNo => "面板项", "Panel item";
    PanelErrNoLabel => "没有标签：请输入中文或英文标签", "it has no label: type a Chinese or an English label";
    PanelErrNotBit => "是字节地址：请写位地址，例如 X0002.3", "is a byte: write a bit address such as X0002.3";
    PanelErrNotByte => "波段开关写一个字节：请写字节地址，例如 X0005", "a knob writes a byte: write a byte address such as X0005";
    PanelErrNotInput => "不是机床输入：按键、开关和波段开关只能写 X 地址", "is not a machine input: keys, switches and knobs write X addresses";
    PanelErrTaken => "已由另一项驱动，请换一个输入地址：", "is already driven by another item; give it another input:";
    PanelErrSameCell => "该格已有另一项，请移到空格：", "that cell already holds another item; move it to a free cell:";
    PanelErrNoPositions => "波段开关没有档位：请至少添加一个", "the knob has no positions: add at least one";
    PanelErrBadPosition => "档位值超出 0–255 或重复：每个档位需要不同的字节值", "a position value is outside 0–255 or used twice: give each position its own byte value";
    CncNotRunning => "CNC 随 PLC 一起运行：开始仿真后这里显示方式、坐标和报警。", "The CNC runs with the PLC: start the simulation to see its mode, positions and alarms here.";
    CncMode => "方式", "Mode";
    CncState => "运行状态", "State";
    CncModeEdit => "编辑", "EDIT";
    CncModeMem => "自动", "AUTO";
    CncModeMdi => "录入", "MDI";
    CncModeHandle => "手脉", "HANDLE";
    CncModeJog => "手动", "JOG";
    CncModeDnc => "DNC", "DNC";
    CncModeRef => "机械回零", "REF";
    CncRunIdle => "复位/空闲", "Idle";
    CncRunRun => "运行中", "Running";
    CncRunHold => "进给保持", "Feed hold";
    CncRunStop => "停止", "Stopped";
    CncProgramNo => "程序号", "Program";
    CncBlockNo => "顺序号", "Block";
    CncProgram => "加工程序", "NC program";
    CncLoadProgram => "载入程序", "Load program";
    CncMdi => "录入（MDI）", "MDI";
    CncSendMdi => "送入 MDI", "Send MDI";
    CncReset => "复位", "RESET";
    CncCycleStart => "循环启动", "Cycle start";
    NoPanelKey => "操作面板上没有此键（在机床操作面板的编辑模式中添加）", "the operator panel has no such key (add it in the panel's edit mode)";
    CncFeedHold => "进给保持", "Feed hold";
    CncMdiSent => "已送入 MDI 程序段数：", "Sent to the CNC's MDI buffer, blocks:";
    CncMdiHow => "在 MDI 方式下按循环启动执行。", "In MDI mode, Cycle start runs it.";
    CncMacros => "宏变量", "Macro variables";
    CncMacroLocals => "局部变量 #1–#33，调用层", "Locals #1–#33, call level";
    CncMacroEditHint => "程序未运行时可改：点数值，输入数字或 vacant，按回车", "Not running: click a value, type a number or vacant, press Enter";
    CncMacroRunning => "程序运行中：只读", "The program runs: read only";
    CncMacroBad => "不是数字，也不是 vacant", "neither a number nor vacant";
    CncMacroVacant => "<空>", "<vacant>";
    CncStopMessage => "程序停止信息（循环启动继续）", "Program stopped (cycle start goes on)";
    CncCurrentLine => "当前程序段：第", "Current block: line";
    CncPickedLine => "点选程序段：第", "Picked block: line";
    CncToolpath => "刀具轨迹", "Toolpath";
    CncToolpathPlot => "刀具轨迹图（点击轨迹选程序段）", "Toolpath plot (click the path to pick its block)";
    CncFit => "适合窗口", "Fit";
    CncBlocks => "个程序段", "blocks";
    CncToolpathStops => "空运行停在第", "The dry run stops at line";
    CncExecuted => "已走轨迹", "Executed";
    CncToolPoint => "刀尖", "Tool";
    CncAxis => "轴", "Axis";
    CncMachinePos => "机床坐标", "Machine";
    CncAbsolutePos => "绝对坐标", "Absolute";
    CncSpindle => "主轴转速", "Spindle speed";
    CncRpm => "转/分", "r/min";
    CncMCode => "M 代码", "M code";
    CncSCode => "S 代码", "S code";
    CncTCode => "T 代码", "T code";
    CncStrobeMf => "MF", "MF";
    CncStrobeSf => "SF", "SF";
    CncStrobeTf => "TF", "TF";
    CncFin => "FIN", "FIN";
    CncDen => "DEN", "DEN";
    CncAlarms => "报警", "Alarms";
    CncNoAlarm => "无报警", "No alarm";
    TracePause => "暂停记录", "Pause";
    TraceResume => "继续记录", "Resume";
    TraceFit => "全部显示", "Fit";
    TraceExport => "导出 CSV", "Export CSV";
    TraceClear => "清除", "Clear";
    TraceRemove => "移除", "Remove";
    TraceSignal => "信号", "Signal";
    TraceValue => "值", "Value";
    TraceTime => "时间 (s)", "Time (s)";
    TraceTick => "扫描周期", "Tick";
    Trigger => "触发", "Trigger";
    TriggerRising => "上升沿", "rising edge";
    TriggerFalling => "下降沿", "falling edge";
    TriggerEqual => "等于", "equals";
    TriggerAbove => "大于", "above";
    TriggerBelow => "小于", "below";
    TriggerPre => "触发前扫描数", "ticks before";
    TriggerPost => "触发后扫描数", "ticks after";
    TriggerArm => "启动触发", "Arm";
    TriggerDisarm => "取消触发", "Disarm";
    TriggerArmed => "等待触发……", "Armed, waiting…";
    TriggerFired => "已触发，正在记录触发后的扫描……", "Triggered, recording the ticks after…";
    TriggerShowCapture => "显示捕获", "Show the capture";
    TriggerCapturedAt => "捕获的触发时刻：扫描", "Captured: triggered at tick";
    TriggerClearCapture => "清除捕获", "Clear the capture";
    TriggerBadSignal => "触发信号无效", "The trigger's signal is wrong";
    TraceNoSignal => "没有记录的信号。", "No signal is traced.";
    TraceHint => "滚轮缩放时间轴，拖动或横向滚动平移，双击或“全部显示”复原，单击放置光标；各信号名旁显示光标处的值。", "Wheel: zoom time, drag or sideways scroll: pan, double-click or Fit: everything, click: place the cursor; each lane shows its value at the cursor beside its name.";
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_message_has_both_languages_and_they_differ_where_they_should() {
        for m in Msg::ALL {
            assert!(
                !m.text(Lang::Zh).is_empty() && !m.text(Lang::En).is_empty(),
                "{m:?}"
            );
        }
        assert_eq!(Lang::from_locale(Some("zh_CN.UTF-8")), Lang::Zh);
        assert_eq!(Lang::from_locale(Some("en_US.UTF-8")), Lang::En);
    }
}
