//! The table of instructions: one row per instruction, from which the macro builds [`Op`]
//! and [`CATALOG`].

use super::areas::*;
use super::operands::*;
use super::{
    Access, CONST_MAX, Category, InstrClass, InstrSpec, OperandKind, Role, TableShape, Width,
};

macro_rules! catalog {
    (
        basic {
            $( $bv:ident $bname:literal $bclass:ident $bcat:ident [$($bo:expr),* $(,)?] $bops:ident? $bzh:literal $ben:literal; )*
        }
        function {
            $(
                $fv:ident $fname:literal Function $fcat:ident
                $(table { first: $first:literal, count: $count:literal, entry: $entry:ident })?
                [$($fo:expr),* $(,)?] $fops:ident? $fzh:literal $fen:literal;
            )*
        }
    ) => {
        /// An opcode: the identity of an instruction; [`Op::spec`] describes it.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[repr(u8)]
        pub enum Op {
            $(
                #[doc = $ben]
                $bv,
            )*
            $(
                #[doc = $fen]
                $fv,
            )*
        }

        /// A function instruction: the [`Op`]s of the table's function rows and no others, so
        /// that a `match` on it must give every function instruction its semantics.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[repr(u8)]
        pub enum FnOp {
            $(
                #[doc = $fen]
                $fv = Op::$fv as u8,
            )*
        }

        impl Op {
            /// The function instruction this is, or `None` for a basic instruction.
            pub const fn function(self) -> Option<FnOp> {
                match self {
                    $(Op::$fv => Some(FnOp::$fv),)*
                    _ => None,
                }
            }
        }

        impl FnOp {
            /// Every function instruction, in catalogue order.
            pub const ALL: &[FnOp] = &[$(FnOp::$fv),*];

            /// The opcode of this function instruction.
            pub const fn op(self) -> Op {
                match self {
                    $(FnOp::$fv => Op::$fv,)*
                }
            }
        }

        /// Every instruction, indexed by `Op as usize`.
        pub static CATALOG: &[InstrSpec] = &[
            $(InstrSpec {
                op: Op::$bv,
                name: $bname,
                class: InstrClass::$bclass,
                category: Category::$bcat,
                operands: catalog!(@ops $bops [$($bo),*]),
                table: None,
                help_zh: $bzh,
                help_en: $ben,
            },)*
            $(InstrSpec {
                op: Op::$fv,
                name: $fname,
                class: InstrClass::Function,
                category: Category::$fcat,
                operands: catalog!(@ops $fops [$($fo),*]),
                table: catalog!(@table $($first $count $entry)?),
                help_zh: $fzh,
                help_en: $fen,
            },)*
        ];
    };
    (@table) => { None };
    (@table $first:literal $count:literal $entry:ident) => {
        Some(TableShape { first: $first, count_from: $count, entry: &$entry })
    };
    (@ops none []) => { &[] };
    (@ops list [$($operand:expr),*]) => { &[$($operand),*] };
    (@ops shared [$operand:expr]) => { $operand };
}

catalog! {
    basic {
        Ld "LD" Contact Basic [bit_in("b", "常开触点地址", "Normally-open contact address")] list?
            "取：以常开触点开始一个逻辑块" "Load: start a logic block with a normally-open contact";
        Ldi "LDI" Contact Basic [bit_in("b", "常闭触点地址", "Normally-closed contact address")] list?
            "取反：以常闭触点开始一个逻辑块" "Load inverse: start a logic block with a normally-closed contact";
        And "AND" Contact Basic [bit_in("b", "串联常开触点地址", "Series normally-open contact address")] list?
            "与：串联一个常开触点" "And: a normally-open contact in series";
        Ani "ANI" Contact Basic [bit_in("b", "串联常闭触点地址", "Series normally-closed contact address")] list?
            "与非：串联一个常闭触点" "And inverse: a normally-closed contact in series";
        Or "OR" Contact Basic [bit_in("b", "并联常开触点地址", "Parallel normally-open contact address")] list?
            "或：并联一个常开触点" "Or: a normally-open contact in parallel";
        Ori "ORI" Contact Basic [bit_in("b", "并联常闭触点地址", "Parallel normally-closed contact address")] list?
            "或非：并联一个常闭触点" "Or inverse: a normally-closed contact in parallel";
        Orb "ORB" Stack Basic [] none?
            "块或：把两个串联块并联" "Or block: connect two series blocks in parallel";
        Anb "ANB" Stack Basic [] none?
            "块与：把两个并联块串联" "And block: connect two parallel blocks in series";
        Mps "MPS" Stack Basic [] none?
            "进栈：保存分支点的运算结果" "Push: save the result at a branch point";
        Mrd "MRD" Stack Basic [] none?
            "读栈：读取分支点的运算结果" "Read: read the result saved at the branch point";
        Mpp "MPP" Stack Basic [] none?
            "出栈：读取并清除分支点的运算结果" "Pop: read and drop the result saved at the branch point";
        Out "OUT" Coil Basic [bit_out("b", BITS_WRITE, "输出线圈地址", "Output coil address")] list?
            "输出：线圈 := 运算结果" "Out: coil := result";
        Outn "OUTN" Coil Basic [bit_out("b", BITS_WRITE, "取反输出线圈地址", "Inverted output coil address")] list?
            "取反输出：线圈 := 运算结果取反" "Out inverted: coil := not result";
    }
    function {
        Set "SET" Function BitOutput [bit_out("OUT", BITS_WRITE, "置位的位地址", "Bit to set")] list?
            "置位：ACT=1 时 OUT := 1" "Set: OUT := 1 while ACT = 1";
        Rst "RST" Function BitOutput [bit_out("OUT", BITS_WRITE, "复位的位地址", "Bit to reset")] list?
            "复位：ACT=1 时 OUT := 0" "Reset: OUT := 0 while ACT = 1";
        Cmp "CMP" Function Compare [
            SIZE_STD,
            signed_in("IN1", Width::SizeOf(0), "比较数据 1：常数或地址", "Value 1: constant or address"),
            signed_in("IN2", Width::SizeOf(0), "比较数据 2：常数或地址", "Value 2: constant or address"),
            bits3_out(RELAYS_WRITE, "结果：OUT=IN1>IN2，OUT+1=相等，OUT+2=IN1<IN2", "Result: OUT = IN1>IN2, OUT+1 = equal, OUT+2 = IN1<IN2"),
        ] list? "二进制数据比较" "Compare binary data";
        Cmpr "CMPR" Function Compare [
            real_in("IN1", "比较实数 1：常数或 D 地址", "Real 1: constant or D address"),
            real_in("IN2", "比较实数 2：常数或 D 地址", "Real 2: constant or D address"),
            bits3_out(CMPR_OUT, "结果：OUT=IN1>IN2，OUT+1=相等，OUT+2=IN1<IN2", "Result: OUT = IN1>IN2, OUT+1 = equal, OUT+2 = IN1<IN2"),
        ] list? "实数比较" "Compare real numbers";
        Tmrb "TMRB" Function TimerCounter [TMRB_OPERANDS] shared?
            "定时器：ACT=1 计时，T≥PT 时 OUT=1；ACT=0 时 T、OUT 清 0" "On-delay timer: times while ACT = 1, OUT = 1 once T ≥ PT; ACT = 0 clears T and OUT";
        Tmrc "TMRC" Function TimerCounter [TMRC_OPERANDS] shared?
            "累计定时器：ACT=0 时保持 T 与 OUT" "Retentive timer: ACT = 0 keeps T and OUT";
        Ctrc "CTRC" Function TimerCounter [
            digits("FMT", 1, "格式 00ab：b=0 加计数/1 减计数，a=初始值 0/1", "Format 00ab: b = 0 up / 1 down, a = initial value 0 / 1"),
            rst("复位：为 1 时 C 回到起始值，OUT := 0", "Reset: 1 returns C to its start value, OUT := 0"),
            with_role(spec("C", OperandKind::Counter, C_ONLY, Width::Bytes(4), Access::ReadWrite, "计数器号 C0–C199", "Counter number C0–C199"), Role::CounterNumber),
            with_role(with_range(spec("N", OperandKind::ConstOrByte, DC_ONLY, Width::Bytes(4), Access::Read, "计数预置值：0–2147483647 的常数或 DC 地址", "Preset: constant 0–2147483647 or DC address"), 0, CONST_MAX), Role::Preset),
            bit_out("OUT", BITS_WRITE, "计数到输出", "Output when the count is reached"),
        ] list? "二进制计数器：ACT 每次上升沿计数一次" "Binary counter: counts each rising edge of ACT";
        Movn "MOVN" Function DataTransfer [
            SIZE_STD,
            signed_in("IN", Width::SizeOf(0), "源数据：常数或地址", "Source: constant or address"),
            byte_out("OUT", BYTES_WRITE, Width::SizeOf(0), "目标地址", "Destination address"),
        ] list? "二进制数据传送：OUT := IN" "Move binary data: OUT := IN";
        Movr "MOVR" Function DataTransfer [
            real_in("IN", "源实数：常数或 D 地址", "Source real: constant or D address"),
            real_out("目标 D 地址", "Destination D address"),
        ] list? "实数拷贝：OUT := IN" "Copy a real: OUT := IN";
        Decb "DECB" Function DataTransfer [
            SIZE_STD,
            byte_in("IN", Width::SizeOf(0), "译码数据地址", "Address of the code to decode"),
            konst("BASE", -CONST_MAX, CONST_MAX, "译码基数", "Base of the decoded range"),
            with_role(byte_out("OUT", RELAYS_WRITE, Width::Bytes(1), "译码结果字节：IN=BASE+k 时位 k 为 1", "Result byte: bit k is 1 when IN = BASE+k"), Role::Driven),
        ] list? "二进制译码：判断 IN 是否为 BASE…BASE+7" "Decode binary: tests IN against BASE…BASE+7";
        Codb "CODB" Function DataTransfer table { first: 4, count: 1, entry: CODB_TABLE_ENTRY } [
            size("SIZE1：输出数据长度 1、2 或 4 字节", "SIZE1: output size 1, 2 or 4 bytes"),
            konst("SIZE2", 1, 256, "转换表数据个数 1–256", "Number of table entries, 1–256"),
            spec("IN", OperandKind::Byte, RELAYS_AND_D, Width::Bytes(1), Access::Read, "表内序号地址（1 字节，无符号）", "Table index address (1 byte, unsigned)"),
            byte_out("OUT", CODB_OUT, Width::SizeOf(0), "输出地址", "Output address"),
        ] list? "二进制代码转换：OUT := 表中第 IN 项" "Code conversion: OUT := the table's entry number IN";
        Jmpb "JMPB" Function LabelJump [spec("L", OperandKind::Label, L_ONLY, Width::None, Access::Read, "跳转目标标号", "Target label")] list?
            "标号跳转：ACT=1 时跳到同一程序块内的 LBL" "Jump: while ACT = 1, go to the LBL in the same block";
        Lbl "LBL" Function LabelJump [spec("L", OperandKind::Label, L_ONLY, Width::None, Access::Read, "标号（每个工程内唯一）", "Label (unique in the project)")] list?
            "标号：JMPB 的目标，单独占一个网络" "Label: target of JMPB, stands alone";
        Call "CALL" Function LabelJump [spec("P", OperandKind::Subprogram, P_ONLY, Width::None, Access::Read, "子程序号", "Subprogram number")] list?
            "调用子程序：ACT=1 时执行子程序 P" "Call: runs subprogram P while ACT = 1";
        Callu "CALLU" Function LabelJump [spec("P", OperandKind::Subprogram, P_ONLY, Width::None, Access::Read, "子程序号", "Subprogram number")] list?
            "无条件调用子程序" "Unconditional subprogram call";
        Rotb "ROTB" Function RotateShift [
            digits("FMT", 1, "格式 abcd：d=编号从 1 起，c=就近旋转，b=目标前一位置，a=输出步数", "Format abcd: d = numbered from 1, c = shortest path, b = position before target, a = output steps"),
            unsigned_in("CNT", Width::SizeOf(2), CONST_MAX, "转子分度数：常数或地址", "Number of positions: constant or address"),
            SIZE_STD,
            only(unsigned_in("IN_W", Width::SizeOf(2), CONST_MAX, "当前位置地址", "Current position address").with_const(false), NO_TC_READ),
            only(unsigned_in("IN_D", Width::SizeOf(2), CONST_MAX, "目标位置地址", "Target position address").with_const(false), NO_TC_READ),
            byte_out("OUTE", NO_TC_WRITE, Width::SizeOf(2), "位置或步数输出地址", "Position or step count output"),
            bit_out("OUTO", BITS_WRITE, "旋转方向：0 正转，1 反转", "Direction: 0 forward, 1 reverse"),
        ] list? "二进制旋转控制：计算刀架等转子的旋转方向和步数" "Rotation control: direction and steps of a turret";
        Pari "PARI" Function Logic [
            digits("OE", 1, "0000 偶校验，0001 奇校验", "0000 even, 0001 odd parity"),
            rst("复位：为 1 时 OUT := 0", "Reset: 1 makes OUT := 0"),
            only(byte_in("IN", Width::Bytes(1), "校验数据（1 字节）", "Data to check (1 byte)"), RELAYS_AND_D),
            with_role(bit_out("OUT", BITS_WRITE, "校验出错输出", "Parity-error output"), Role::Driven),
        ] list? "奇偶校验" "Parity check";
        Addb "ADDB" Function IntegerMath [ARITH_B] shared? "二进制加法：OUT := IN1 + IN2" "Binary add: OUT := IN1 + IN2";
        Addr "ADDR" Function RealMath [ARITH_R] shared? "实数加法" "Real add";
        Subb "SUBB" Function IntegerMath [ARITH_B] shared? "二进制减法：OUT := IN1 − IN2" "Binary subtract: OUT := IN1 − IN2";
        Subr "SUBR" Function RealMath [ARITH_R] shared? "实数减法" "Real subtract";
        Difu "DIFU" Function BitOutput [ONE_BIT_OUT] shared? "上升沿置位：ACT 由 0 变 1 的一个扫描周期 OUT=1" "Rising edge: OUT = 1 for the scan where ACT goes 0→1";
        Difd "DIFD" Function BitOutput [ONE_BIT_OUT] shared? "下降沿置位：ACT 由 1 变 0 的一个扫描周期 OUT=1" "Falling edge: OUT = 1 for the scan where ACT goes 1→0";
        Alt "ALT" Function BitOutput [
            spec("OUT", OperandKind::Bit, BITS_WRITE, Width::None, Access::ReadWrite, "交替输出的位地址", "Bit to toggle"),
        ] list? "交替输出：ACT 每次上升沿 OUT 取反" "Alternate: OUT toggles on each rising edge of ACT";
        Move "MOVE" Function DataTransfer [
            digits("H", 1, "高 4 位屏蔽（二进制）", "High 4 mask bits (binary)"),
            digits("L", 1, "低 4 位屏蔽（二进制）", "Low 4 mask bits (binary)"),
            only(byte_in("IN", Width::Bytes(1), "源字节地址", "Source byte address"), RELAYS_AND_D),
            byte_out("OUT", MOVE_OUT, Width::Bytes(1), "目标字节地址", "Destination byte address"),
        ] list? "逻辑乘：OUT := IN ∧ 屏蔽" "Logical product: OUT := IN ∧ mask";
        Wand "WAND" Function Logic [WORD_LOGIC] shared? "二进制字节与" "Bitwise and";
        Wor "WOR" Function Logic [WORD_LOGIC] shared? "二进制字节或" "Bitwise or";
        Wxor "WXOR" Function Logic [WORD_LOGIC] shared? "二进制字节异或" "Bitwise exclusive or";
        Winv "WINV" Function Logic [
            SIZE_STD,
            signed_in("IN", Width::SizeOf(0), "源数据：常数或地址", "Source: constant or address"),
            byte_out("OUT", BYTES_WRITE, Width::SizeOf(0), "结果输出地址", "Result address"),
        ] list? "二进制字节取反" "Bitwise not";
        Wshl "WSHL" Function RotateShift [SHIFT] shared? "二进制数据左移" "Shift left";
        Wshr "WSHR" Function RotateShift [SHIFT] shared? "二进制数据右移" "Shift right";
        Mulb "MULB" Function IntegerMath [MUL_DIV_B] shared? "二进制乘法：16 位 × 16 位 → 32 位" "Binary multiply: 16 × 16 → 32 bits";
        Mulr "MULR" Function RealMath [MUL_DIV_R] shared? "实数乘法" "Real multiply";
        Divb "DIVB" Function IntegerMath [MUL_DIV_B] shared? "16 位二进制除法：低 16 位商，高 16 位余数" "16-bit divide: quotient in the low, remainder in the high 16 bits";
        Divr "DIVR" Function RealMath [MUL_DIV_R] shared? "实数除法" "Real divide";
        Windr "WINDR" Function Cnc [
            spec("IN", OperandKind::Byte, D_ONLY, Width::Table, Access::ReadWrite, "窗口数据块首地址（D）", "First D address of the window block"),
            with_role(spec("ERR", OperandKind::BitOrByte, BYTES_WRITE, Width::Bytes(1), Access::Write, "完成输出：处理结束时为 1", "Completion output: 1 when processing has ended"), Role::Driven),
        ] list? "读写 CNC 窗口数据" "CNC window read/write";
        Axctl "AXCTL" Function Cnc [
            with_range(unsigned_in("GRP", Width::Bytes(1), 4, "控制组 1–4（A–D）", "Control group 1–4 (A–D)"), 1, 4),
            unsigned_in("CMD", Width::Bytes(1), 255, "控制指令（见轴控指令表）", "Command (see the axis-command table)"),
            signed_in("DT1", Width::Bytes(2), "数据 1：速度", "Data 1: speed"),
            signed_in("DT2", Width::Bytes(4), "数据 2：距离、位置、时间或代码", "Data 2: distance, position, time or code"),
            rst("复位：为 1 时复位 PLC 轴", "Reset: 1 resets the PLC axis"),
            bit_out("FIN", BITS_WRITE, "完成输出", "Completion output"),
            err("错误输出", "Error output"),
        ] list? "PLC 轴控制" "PLC axis control";
        Xmov "XMOV" Function DataTransfer [
            konst("RW", 0, 1, "0 读表，1 写表", "0 read from the table, 1 write to it"),
            digits("FMT", 9, "格式 0nnx：nn 个数，x 元素宽度 1/2/4", "Format 0nnx: nn elements of x bytes (1/2/4)"),
            unsigned_in("DL", Width::Bytes(2), 16384, "表长度：常数或地址", "Table length: constant or address"),
            spec("DS", OperandKind::Byte, BYTES_READ, Width::Table, Access::WriteWhen { operand: 0, value: 1 }, "数据表首地址", "First address of the table"),
            spec("DD", OperandKind::Byte, BYTES_WRITE, Width::Table, Access::WriteWhen { operand: 0, value: 0 }, "输入/输出数据地址", "Data address read or written"),
            only(byte_in("DI", Width::Table, "索引地址（从 0 开始）", "Index address (from 0)"), BYTES_WRITE),
            rst("复位：为 1 时 ERR := 0，不传送", "Reset: 1 makes ERR := 0 and moves nothing"),
            err("错误输出：索引超出表长", "Error output: an index past the table"),
        ] list? "二进制索引数据传送" "Indexed table move";
        Dschb "DSCHB" Function DataTransfer [
            SIZE_STD,
            only(byte_in("IN1", Width::Table, "数据表首地址", "First address of the table"), NO_TC_READ),
            only(unsigned_in("INL", Width::Bytes(2), 65535, "表中数据个数：常数或地址", "Number of entries: constant or address"), NO_TC_READ),
            only(signed_in("DS", Width::SizeOf(0), "检索数据：常数或地址", "Value to search for: constant or address"), NO_TC_READ),
            byte_out("DI", NO_TC_WRITE, Width::SizeOf(0), "检索结果（序号）地址", "Result (index) address"),
            err("错误输出：未找到时为 1", "Error output: 1 when not found"),
        ] list? "数据检索：在表中查找数据" "Search a table for a value";
        Psgnl "PSGNL" Function Cnc [
            unsigned_in("AXIS", Width::Bytes(1), 255, "轴号：1、2…；第二通道 21、22…", "Axis number: 1, 2 …; second channel 21, 22 …"),
            spec("AREA", OperandKind::Byte, BYTES_READ, Width::Elements4(7), Access::Read, "7 个递增的区域边界（4 字节）", "7 ascending zone boundaries (4 bytes each)"),
            byte_out("OUT", BYTES_WRITE, Width::Bytes(1), "区域输出字节", "Zone output byte"),
            err("错误输出", "Error output"),
        ] list? "位置信号输出：机床坐标所在的区域" "Position signal: the zone of the machine coordinate";
        Psgn2 "PSGN2" Function Cnc [
            unsigned_in("AXIS", Width::Bytes(1), 255, "轴号", "Axis number"),
            signed_in("MIN", Width::Bytes(4), "区域下限（非负）", "Lower bound (not negative)"),
            signed_in("MAX", Width::Bytes(4), "区域上限", "Upper bound"),
            bit_out("OUT", BITS_WRITE, "在区域内时为 1", "1 inside the zone"),
            err("错误输出", "Error output"),
        ] list? "位置信号输出 2：机床坐标是否在区域内" "Position signal 2: is the machine coordinate inside the zone";
        Zcp "ZCP" Function Compare [
            SIZE_STD,
            only(signed_in("IN1", Width::SizeOf(0), "区域下限", "Lower bound"), NO_PRESETS_READ),
            only(signed_in("IN2", Width::SizeOf(0), "区域上限", "Upper bound"), NO_PRESETS_READ),
            only(signed_in("IN3", Width::SizeOf(0), "比较数据", "Value to compare"), NO_PRESETS_READ),
            bits3_out(RELAYS_WRITE, "结果：OUT=低于下限，OUT+1=区域内，OUT+2=高于上限", "Result: OUT = below, OUT+1 = inside, OUT+2 = above"),
        ] list? "区域比较" "Zone compare";
        Sin "SIN" Function RealMath [TRIG] shared? "正弦" "Sine";
        Cos "COS" Function RealMath [TRIG] shared? "余弦" "Cosine";
        Tan "TAN" Function RealMath [TRIG] shared? "正切" "Tangent";
        Sqrt "SQRT" Function RealMath [
            real_in("IN", "输入：实数常数或 D 地址", "Input: real constant or D address"),
            real_out("实数结果（D 地址）", "Real result (D address)"),
            RST_ERR,
            REAL_ERR_LATCHED,
        ] list? "求平方根" "Square root";
        Dtr "DTR" Function RealMath [
            spec("IN", OperandKind::ConstOrByte, D_ONLY, Width::Bytes(4), Access::Read, "整数：常数或 D 地址", "Integer: constant or D address"),
            real_out("实数结果（D 地址）", "Real result (D address)"),
            RST_ERR,
            REAL_ERR_LATCHED,
        ] list? "整数转换为实数" "Integer to real";
        Round "ROUND" Function RealMath [
            real_in("IN", "实数：常数或 D 地址", "Real: constant or D address"),
            real_out("整数结果（D 地址）", "Integer result (D address)"),
            RST_ERR,
            REAL_ERR_LATCHED,
        ] list? "实数四舍五入转换为整数" "Round a real to an integer";
    }
}
