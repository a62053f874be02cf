//! Reading a written PDF back: lopdf parses it (so it is well-formed), and the text of each
//! page is decoded through the font's ToUnicode map, as a PDF viewer's search does.

use std::collections::HashMap;

/// Parses a ToUnicode CMap's `bfchar` and `bfrange` entries (code → text).
fn cmap(text: &str) -> HashMap<u32, String> {
    let hex = |s: &str| u32::from_str_radix(s.trim_matches(|c| c == '<' || c == '>'), 16).ok();
    let utf16 = |s: &str| {
        let s = s.trim_matches(|c| c == '<' || c == '>');
        let units: Vec<u16> = (0..s.len() / 4)
            .filter_map(|i| u16::from_str_radix(&s[i * 4..i * 4 + 4], 16).ok())
            .collect();
        String::from_utf16_lossy(&units)
    };
    let mut map = HashMap::new();
    let mut mode = "";
    for line in text.lines() {
        let line = line.trim();
        if line.ends_with("beginbfchar") {
            mode = "char";
            continue;
        }
        if line.ends_with("beginbfrange") {
            mode = "range";
            continue;
        }
        if line.starts_with("endbf") {
            mode = "";
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        match (mode, words.as_slice()) {
            ("char", [code, text]) => {
                if let Some(c) = hex(code) {
                    map.insert(c, utf16(text));
                }
            }
            ("range", [lo, hi, start]) => {
                if let (Some(lo), Some(hi)) = (hex(lo), hex(hi)) {
                    let first: Vec<u16> = utf16(start).encode_utf16().collect();
                    for (k, code) in (lo..=hi).enumerate() {
                        let mut units = first.clone();
                        if let Some(last) = units.last_mut() {
                            *last += k as u16;
                        }
                        map.insert(code, String::from_utf16_lossy(&units));
                    }
                }
            }
            _ => {}
        }
    }
    map
}

/// The text of every page, one line per text object.
pub fn pdf_pages(bytes: &[u8]) -> Vec<String> {
    let doc = lopdf::Document::load_mem(bytes).expect("the PDF parses");
    let mut pages = Vec::new();
    for (_, page) in doc.get_pages() {
        let mut maps: HashMap<Vec<u8>, HashMap<u32, String>> = HashMap::new();
        for (name, font) in doc.get_page_fonts(page).expect("the page's fonts") {
            let id = font
                .get(b"ToUnicode")
                .and_then(|o| o.as_reference())
                .expect("every font maps its glyphs to text");
            let stream = doc.get_object(id).unwrap().as_stream().unwrap();
            let data = stream
                .decompressed_content()
                .unwrap_or_else(|_| stream.content.clone());
            maps.insert(name, cmap(&String::from_utf8_lossy(&data)));
        }
        let content = doc.get_page_content(page).expect("the page's content");
        let ops = lopdf::content::Content::decode(&content).expect("the content parses");
        let mut text = String::new();
        let mut font: Vec<u8> = Vec::new();
        let decode = |bytes: &[u8], font: &[u8], text: &mut String| {
            let map = &maps[font];
            for pair in bytes.chunks(2) {
                let code = pair.iter().fold(0u32, |a, b| a << 8 | u32::from(*b));
                text.push_str(map.get(&code).map_or("\u{fffd}", String::as_str));
            }
        };
        for op in &ops.operations {
            match op.operator.as_str() {
                "Tf" => font = op.operands[0].as_name().unwrap().to_vec(),
                "Tj" => decode(op.operands[0].as_str().unwrap(), &font, &mut text),
                "TJ" => {
                    for part in op.operands[0].as_array().unwrap() {
                        if let Ok(s) = part.as_str() {
                            decode(s, &font, &mut text);
                        }
                    }
                }
                "ET" => text.push('\n'),
                _ => {}
            }
        }
        pages.push(text);
    }
    pages
}
