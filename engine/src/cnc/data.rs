//! CNC data the PLC reads and writes through WINDR and scripts set up: tool offsets,
//! workpiece offsets, macro variables and the clock (docs/cnc.md, "CNC data").

/// Tool offset numbers kept (0–99: the GSK988TA uses 1–99, the GSK980 0–32).
pub const TOOL_OFFSETS: usize = 100;

/// One tool offset, in least increments (X as a diameter).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ToolOffset {
    /// Geometry X, Z, R, Y.
    pub geometry: [i64; 4],
    /// Wear X, Z, R, Y.
    pub wear: [i64; 4],
    /// Imaginary tip direction 0–9.
    pub tip: i64,
}

/// What a tool-offset value is: geometry or wear of X, Z, R, Y, or the tip.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OffsetType {
    /// Geometry of X (0), Z (1), R (2), Y (3).
    Geometry(usize),
    /// Wear of X, Z, R, Y.
    Wear(usize),
    /// Imaginary tip direction.
    Tip,
}

impl OffsetType {
    /// The script spelling: X Z R Y, WX WZ WR WY, TIP.
    pub fn parse(text: &str) -> Option<OffsetType> {
        let t = text.to_ascii_uppercase();
        let axis = |c: &str| ["X", "Z", "R", "Y"].iter().position(|a| *a == c);
        if t == "TIP" {
            return Some(OffsetType::Tip);
        }
        if let Some(rest) = t.strip_prefix('W') {
            return axis(rest).map(OffsetType::Wear);
        }
        axis(&t).map(OffsetType::Geometry)
    }

    /// The script spelling.
    pub fn name(self) -> &'static str {
        match self {
            OffsetType::Geometry(k) => ["X", "Z", "R", "Y"][k],
            OffsetType::Wear(k) => ["WX", "WZ", "WR", "WY"][k],
            OffsetType::Tip => "TIP",
        }
    }

    /// The GSK988TA WINDR type code 0–9 (7 is read as the tip, like 6).
    pub fn from_988(code: i32) -> Option<OffsetType> {
        Some(match code {
            0 => OffsetType::Geometry(0),
            1 => OffsetType::Wear(0),
            2 => OffsetType::Geometry(1),
            3 => OffsetType::Wear(1),
            4 => OffsetType::Geometry(2),
            5 => OffsetType::Wear(2),
            6 | 7 => OffsetType::Tip,
            8 => OffsetType::Geometry(3),
            9 => OffsetType::Wear(3),
            _ => return None,
        })
    }

    /// The GSK980 WINDR type code: 1–5 geometry of X Z Y 4th 5th, 99 R, 100 tip, 101–105 wear,
    /// 199 wear R. Axes 4 and 5 have no offset here and read as 0 (`None` inside).
    pub fn from_980(code: i32) -> Option<Option<OffsetType>> {
        Some(match code {
            1 => Some(OffsetType::Geometry(0)),
            2 => Some(OffsetType::Geometry(1)),
            3 => Some(OffsetType::Geometry(3)),
            4 | 5 | 104 | 105 => None,
            99 => Some(OffsetType::Geometry(2)),
            100 => Some(OffsetType::Tip),
            101 => Some(OffsetType::Wear(0)),
            102 => Some(OffsetType::Wear(1)),
            103 => Some(OffsetType::Wear(3)),
            199 => Some(OffsetType::Wear(2)),
            _ => return None,
        })
    }
}

impl ToolOffset {
    /// The value of one type.
    pub fn get(&self, t: OffsetType) -> i64 {
        match t {
            OffsetType::Geometry(k) => self.geometry[k],
            OffsetType::Wear(k) => self.wear[k],
            OffsetType::Tip => self.tip,
        }
    }

    /// Sets one type.
    pub fn set(&mut self, t: OffsetType, v: i64) {
        match t {
            OffsetType::Geometry(k) => self.geometry[k] = v,
            OffsetType::Wear(k) => self.wear[k] = v,
            OffsetType::Tip => self.tip = v,
        }
    }

    /// Geometry plus wear along axis slot `n` (0 X, 1 Z, 2 Y; axes 4 and 5 have none).
    pub fn along(&self, n: usize) -> i64 {
        match n {
            0 => self.geometry[0] + self.wear[0],
            1 => self.geometry[1] + self.wear[1],
            2 => self.geometry[3] + self.wear[3],
            _ => 0,
        }
    }
}

/// Workpiece systems: EXT, G54 … G59.
pub const WORK_SYSTEMS: [&str; 7] = ["EXT", "G54", "G55", "G56", "G57", "G58", "G59"];

/// Index of a workpiece system name (EXT = 0, G54 = 1 …).
pub fn work_system(text: &str) -> Option<usize> {
    WORK_SYSTEMS
        .iter()
        .position(|s| s.eq_ignore_ascii_case(text))
}

/// Macro variables: common #100–#199 (vacant at power-on), #500–#999 (kept).
#[derive(Clone, Debug)]
pub struct Macros {
    /// #100–#199.
    pub volatile: [Option<f64>; 100],
    /// #500–#999.
    pub kept: Vec<Option<f64>>,
    /// #1100–#1131 as 32 bits (bit k = #1100+k), written to F214–F217.
    pub outputs: u32,
    /// #3001: its value when last set, ms.
    pub timer_base: f64,
    /// The virtual time #3001 was last set at, ms.
    pub timer_at: u64,
    /// #3002: its value when last set, hours.
    pub hours_base: f64,
    /// Time in cycle start (STL) since #3002 was last set, ms.
    pub run_ms: u64,
    /// The alarm #3000 raised last and its message.
    pub message: Option<(u16, String)>,
    /// The message of the stop #3006 made, shown until cycle start or reset.
    pub stop_message: Option<String>,
}

impl Default for Macros {
    fn default() -> Self {
        Macros {
            volatile: [None; 100],
            kept: vec![None; 500],
            outputs: 0,
            timer_base: 0.0,
            timer_at: 0,
            hours_base: 0.0,
            run_ms: 0,
            message: None,
            stop_message: None,
        }
    }
}

/// Where a macro variable number lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MacroSlot {
    /// #1–#33: local, none outside macro programs.
    Local,
    /// #100–#199 (index 0–99).
    Volatile(usize),
    /// #500–#999 (index 0–499).
    Kept(usize),
    /// #1000–#1031, read only: a G bit.
    Input(u32),
    /// #1100–#1131: an F bit.
    Output(u32),
    /// No such variable.
    Missing,
}

impl MacroSlot {
    /// The slot of variable `n`.
    pub fn of(n: i64) -> MacroSlot {
        match n {
            1..=33 => MacroSlot::Local,
            100..=199 => MacroSlot::Volatile((n - 100) as usize),
            500..=999 => MacroSlot::Kept((n - 500) as usize),
            1000..=1031 => MacroSlot::Input((n - 1000) as u32),
            1100..=1131 => MacroSlot::Output((n - 1100) as u32),
            _ => MacroSlot::Missing,
        }
    }
}

/// Seconds from 1970-01-01 of a civil date-time (proleptic Gregorian).
pub fn epoch_seconds(y: i64, mo: i64, d: i64, h: i64, mi: i64, s: i64) -> i64 {
    // Days from civil (H. Hinnant's algorithm).
    let y = if mo <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (mo + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    let days = era * 146_097 + doe - 719_468;
    days * 86_400 + h * 3600 + mi * 60 + s
}

/// The civil date-time of seconds from 1970-01-01: year, month, day, hour, minute, second.
pub fn civil(t: i64) -> [i64; 6] {
    let days = t.div_euclid(86_400);
    let secs = t.rem_euclid(86_400);
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    [y, m, d, secs / 3600, secs / 60 % 60, secs % 60]
}

/// Parses `YYYY-MM-DDTHH:MM:SS` into seconds from 1970, checking every field.
pub fn parse_clock(text: &str) -> Option<i64> {
    let (date, time) = text.split_once(['T', 't'])?;
    let num = |s: &str, len: usize| -> Option<i64> {
        (s.len() == len && s.bytes().all(|b| b.is_ascii_digit()))
            .then(|| s.parse().ok())
            .flatten()
    };
    let d: Vec<&str> = date.split('-').collect();
    let t: Vec<&str> = time.split(':').collect();
    if d.len() != 3 || t.len() != 3 {
        return None;
    }
    let (y, mo, da) = (num(d[0], 4)?, num(d[1], 2)?, num(d[2], 2)?);
    let (h, mi, s) = (num(t[0], 2)?, num(t[1], 2)?, num(t[2], 2)?);
    if !(1..=12).contains(&mo) || da < 1 || h > 23 || mi > 59 || s > 59 {
        return None;
    }
    let secs = epoch_seconds(y, mo, da, h, mi, s);
    // A day past the month's end comes back as another date.
    (civil(secs) == [y, mo, da, h, mi, s]).then_some(secs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clock_round_trips_and_refuses_impossible_dates() {
        let t = parse_clock("2026-01-01T00:00:00").unwrap();
        assert_eq!(civil(t), [2026, 1, 1, 0, 0, 0]);
        assert_eq!(civil(t + 86_400 * 59 + 3661), [2026, 3, 1, 1, 1, 1]);
        let leap = parse_clock("2028-02-29T23:59:59").unwrap();
        assert_eq!(civil(leap + 1), [2028, 3, 1, 0, 0, 0]);
        assert!(parse_clock("2026-02-29T00:00:00").is_none());
        assert!(parse_clock("2026-13-01T00:00:00").is_none());
        assert!(parse_clock("2026-01-01 00:00:00").is_none());
        assert!(parse_clock("2026-1-01T00:00:00").is_none());
    }

    #[test]
    fn offset_types_read_both_profiles_codes() {
        assert_eq!(OffsetType::parse("wz"), Some(OffsetType::Wear(1)));
        assert_eq!(OffsetType::parse("Tip"), Some(OffsetType::Tip));
        assert_eq!(OffsetType::parse("Q"), None);
        assert_eq!(OffsetType::from_988(8), Some(OffsetType::Geometry(3)));
        assert_eq!(OffsetType::from_988(10), None);
        assert_eq!(OffsetType::from_980(199), Some(Some(OffsetType::Wear(2))));
        assert_eq!(OffsetType::from_980(4), Some(None));
        assert_eq!(OffsetType::from_980(200), None);
    }
}
