//! The title page: the project, its controller, version information, date, step counts and
//! the contents with page numbers.

use crate::font::Metrics;
use crate::options::Options;
use crate::page::{Anchor, Ink, Item, Pt};
use crate::pages::Frame;
use ladder_engine::model::Project;
use ladder_engine::profile::Profile;

/// The items of the title page.
pub(crate) fn title_page(
    project: &Project,
    name: &str,
    options: &Options,
    frame: &Frame,
    contents: &[(String, usize)],
    metrics: &mut Metrics,
) -> Vec<Item> {
    let lang = options.lang;
    let mut items = Vec::new();
    let width = frame.right - frame.left;
    let mid = frame.left + width / 2.0;
    let mut y = frame.top + 80.0;
    for line in metrics.wrap(name, 22.0, width) {
        items.push(Item::text(mid, y, 22.0, Anchor::Middle, Ink::Black, line));
        y += 28.0;
    }
    items.push(Item::text(
        mid,
        y,
        12.0,
        Anchor::Middle,
        Ink::Grey,
        lang.say("PLC ladder program", "PLC 梯形图程序"),
    ));
    y += 48.0;
    let steps = ladder_engine::compiler::compile(project).steps;
    let v = &project.version;
    let rows: Vec<(String, String)> = vec![
        (
            lang.say("Controller", "控制器"),
            Profile::get(project.profile).name.to_string(),
        ),
        (lang.say("Designer", "设计者"), v.designer.clone()),
        (lang.say("Version", "版本"), v.version.clone()),
        (lang.say("Remarks", "备注"), v.remarks.clone()),
        (lang.say("Date", "日期"), options.date.clone()),
        (
            lang.say("Steps", "步数"),
            format!(
                "{} {}  ·  {} {}  ·  {} {}  ·  {} {}",
                lang.say("level 1", "第1级"),
                steps.level1,
                lang.say("level 2", "第2级"),
                steps.level2,
                lang.say("subprograms", "子程序"),
                steps.subprograms,
                lang.say("total", "合计"),
                steps.total
            ),
        ),
    ];
    let key_x = frame.left + width * 0.18;
    let value_x = frame.left + width * 0.38;
    for (key, value) in rows {
        items.push(Item::text(key_x, y, 10.0, Anchor::Left, Ink::Grey, key));
        for line in metrics.wrap(&value, 10.0, frame.right - value_x) {
            items.push(Item::text(value_x, y, 10.0, Anchor::Left, Ink::Black, line));
            y += 15.0;
        }
        if value.is_empty() {
            y += 15.0;
        }
        y += 3.0;
    }
    y += 30.0;
    items.push(Item::text(
        key_x,
        y,
        12.0,
        Anchor::Left,
        Ink::Black,
        lang.say("Contents", "目录"),
    ));
    y += 20.0;
    let right = frame.right - width * 0.18;
    for (section, page) in contents {
        if y > frame.bottom {
            break;
        }
        let text = metrics.fit(section, 10.0, right - key_x - 40.0);
        items.push(Item::text(key_x, y, 10.0, Anchor::Left, Ink::Black, text));
        items.push(Item::text(
            right,
            y,
            10.0,
            Anchor::Right,
            Ink::Black,
            page.to_string(),
        ));
        y += 15.0;
    }
    let _: Pt = y;
    items
}
