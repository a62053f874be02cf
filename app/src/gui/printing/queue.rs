//! The system's print queue behind a small trait, like the file dialogs, so tests script it.

use std::sync::{Arc, Mutex};

/// The printers a queue offers, and the system's default among them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Printers {
    /// Their names, as the print system lists them.
    pub names: Vec<String>,
    /// The system's default printer, when it has one.
    pub default: Option<String>,
}

/// Where a print job goes.
pub trait PrintQueue {
    /// Whether there is a queue to send to.
    fn available(&self) -> bool;
    /// The printers to choose from.
    fn printers(&self) -> Printers;
    /// Sends a PDF to `printer` (the default when `None`); the answer is the queue's own
    /// words (`request id is …`) or why it refused.
    fn submit(&mut self, pdf: &[u8], title: &str, printer: Option<&str>) -> Result<String, String>;
}

/// The system's queue: CUPS's `lp` and `lpstat`, where they are on the PATH.
#[derive(Default)]
pub struct LpQueue;

fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(program).is_file()))
}

/// What `lpstat ARG` writes, when it runs.
fn lpstat(arg: &str) -> String {
    std::process::Command::new("lpstat")
        .arg(arg)
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).into_owned())
        .unwrap_or_default()
}

/// The printers of `lpstat -a` (`NAME accepting requests since …`) and the default of
/// `lpstat -d` (`system default destination: NAME`).
pub fn parse_lpstat(accepting: &str, default: &str) -> Printers {
    let names: Vec<String> = accepting
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .map(str::to_string)
        .collect();
    let default = default
        .lines()
        .find_map(|l| l.rsplit_once(": "))
        .map(|(_, name)| name.trim().to_string())
        .filter(|n| names.contains(n));
    Printers { names, default }
}

impl PrintQueue for LpQueue {
    fn available(&self) -> bool {
        on_path("lp")
    }

    fn printers(&self) -> Printers {
        if !on_path("lpstat") {
            return Printers::default();
        }
        parse_lpstat(&lpstat("-a"), &lpstat("-d"))
    }

    fn submit(&mut self, pdf: &[u8], title: &str, printer: Option<&str>) -> Result<String, String> {
        let file =
            std::env::temp_dir().join(format!("ladder-studio-print-{}.pdf", std::process::id()));
        std::fs::write(&file, pdf).map_err(|e| format!("{}: {e}", file.display()))?;
        // lp copies the file into the spool before it answers, so it can go at once.
        let mut lp = std::process::Command::new("lp");
        if let Some(p) = printer {
            lp.arg("-d").arg(p);
        }
        let run = lp.arg("-t").arg(title).arg("--").arg(&file).output();
        let _ = std::fs::remove_file(&file);
        match run {
            Ok(o) if o.status.success() => {
                Ok(String::from_utf8_lossy(&o.stdout).trim().to_string())
            }
            Ok(o) => Err(String::from_utf8_lossy(&o.stderr).trim().to_string()),
            Err(e) => Err(format!("lp: {e}")),
        }
    }
}

/// A job a scripted queue received: the PDF and the printer it was sent to.
pub type Job = (Vec<u8>, Option<String>);

/// A queue for tests: it keeps every PDF it is sent, with the printer it went to.
#[derive(Clone, Default)]
pub struct ScriptedQueue {
    /// The PDFs received, in order, with their printer.
    pub jobs: Arc<Mutex<Vec<Job>>>,
    /// Whether the system has a queue (else Print saves the PDF).
    pub present: bool,
    /// The printers it offers.
    pub printers: Printers,
}

impl PrintQueue for ScriptedQueue {
    fn available(&self) -> bool {
        self.present
    }

    fn printers(&self) -> Printers {
        self.printers.clone()
    }

    fn submit(
        &mut self,
        pdf: &[u8],
        _title: &str,
        printer: Option<&str>,
    ) -> Result<String, String> {
        let mut jobs = self
            .jobs
            .lock()
            .map_err(|_| "the queue is gone".to_string())?;
        jobs.push((pdf.to_vec(), printer.map(str::to_string)));
        Ok(format!("request id is scripted-{}", jobs.len()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lpstat_lists_the_printers_and_the_default() {
        let a = "office accepting requests since Tue 01 Dec 2026\nshop-floor accepting requests since Wed 02 Dec 2026\n";
        let p = parse_lpstat(a, "system default destination: shop-floor\n");
        assert_eq!(p.names, ["office", "shop-floor"]);
        assert_eq!(p.default.as_deref(), Some("shop-floor"));
        let none = parse_lpstat(a, "no system default destination\n");
        assert_eq!(none.default, None);
        assert_eq!(parse_lpstat("", ""), Printers::default());
    }
}
