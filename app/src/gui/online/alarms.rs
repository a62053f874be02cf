//! The PLC alarm list: the A bits that are on and have a row in the display-message table,
//! with number, text and the tick each came on, as the CNC's alarm screen lists them.

use super::session::Session;
use ladder_engine::Address;
use ladder_engine::address::Area;
use ladder_engine::model::Project;

/// One alarm or operator message on the list.
#[derive(Clone, Debug, PartialEq)]
pub struct PlcAlarm {
    /// Its A bit.
    pub bit: Address,
    /// Its number (1000–1999 alarms, 2000–9999 operator messages).
    pub number: u16,
    /// The tick it came on.
    pub since: u64,
}

/// The alarms on now, in the order they came on.
#[derive(Clone, Debug, Default)]
pub struct AlarmList {
    /// The list.
    pub on: Vec<PlcAlarm>,
}

impl AlarmList {
    /// Brings the list up to the state shown.
    pub fn update(&mut self, project: &Project, s: &Session) {
        let src = s.source();
        let now = s.scrub.unwrap_or(s.published.snapshot.ticks);
        let mut still = Vec::with_capacity(self.on.len());
        for (k, row) in project.messages.rows.iter().enumerate() {
            let Some(number) = row.number else { continue };
            let bit = Address {
                area: Area::A,
                number: (k / 8) as u16,
                bit: Some((k % 8) as u8),
            };
            if !src.bit(bit) {
                continue;
            }
            let since = match self.on.iter().find(|a| a.bit == bit) {
                Some(a) => a.since,
                None => {
                    // The exact tick from the recorder when it has it.
                    let loc = s.running.layout.loc(bit, false);
                    s.recorder()
                        .last_change(now, loc.off, 1 << (k % 8))
                        .unwrap_or(now)
                }
            };
            still.push(PlcAlarm { bit, number, since });
        }
        still.sort_by_key(|a| (a.since, a.number));
        self.on = still;
    }

    /// The text of an entry in a language (`zh`, `en`), from the message table.
    pub fn text(project: &Project, a: &PlcAlarm, lang: &str) -> String {
        let k = usize::from(a.bit.number) * 8 + usize::from(a.bit.bit.unwrap_or(0));
        project
            .messages
            .rows
            .get(k)
            .and_then(|r| r.texts.get(lang).or_else(|| r.texts.values().next()))
            .cloned()
            .unwrap_or_default()
    }
}
