//! The page around the sections: escaping, tables, the inline style and script.
//!
//! Everything the page needs is in the file: the style sheet and the script are inlined, every
//! figure is inline SVG (the charts, drawn here from numbers) or a `data:` image (pictures of
//! walks and figures read from a results folder, which an `<img>` shows without running
//! anything they might contain). A Content-Security-Policy forbids every fetch, so that even
//! a planted link cannot make the page send a request.

use std::fmt::Write;

/// `text` escaped for HTML text and attribute values.
pub fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// An anchor name made of `text`'s letters and digits (others become `-`), as finding files
/// are named.
pub fn anchor(text: &str) -> String {
    crate::claims::findings::claim_slug(text)
}

/// One table cell: its HTML content and an optional class (e.g. a verdict colour).
#[derive(Clone, Debug, Default)]
pub struct Cell {
    pub html: String,
    pub class: &'static str,
    /// The value the sort uses when it is not the text (e.g. a number shown rounded).
    pub sort: Option<String>,
}

impl Cell {
    /// A cell of plain text.
    pub fn text(text: impl AsRef<str>) -> Cell {
        Cell {
            html: esc(text.as_ref()),
            ..Cell::default()
        }
    }

    /// A cell of HTML made by the caller (escaped already).
    pub fn html(html: String) -> Cell {
        Cell {
            html,
            ..Cell::default()
        }
    }

    pub fn class(mut self, class: &'static str) -> Cell {
        self.class = class;
        self
    }
}

/// A sortable, filterable table with id `id` (a filter box above it when it has more than a
/// few rows).
pub fn table(id: &str, header: &[&str], rows: &[Vec<Cell>]) -> String {
    let mut s = String::new();
    if rows.len() > 8 {
        let _ = write!(
            s,
            r#"<p><input class="filter" type="search" placeholder="filter rows" data-table="{}"> <span class="count" id="{}-count">{} rows</span></p>"#,
            esc(id),
            esc(id),
            rows.len()
        );
    }
    let _ = write!(
        s,
        r#"<div class="scroll"><table class="sortable" id="{}"><thead><tr>"#,
        esc(id)
    );
    for h in header {
        let _ = write!(s, "<th>{}</th>", esc(h));
    }
    s.push_str("</tr></thead><tbody>\n");
    for row in rows {
        s.push_str("<tr>");
        for c in row {
            s.push_str("<td");
            if !c.class.is_empty() {
                let _ = write!(s, r#" class="{}""#, c.class);
            }
            if let Some(v) = &c.sort {
                let _ = write!(s, r#" data-sort="{}""#, esc(v));
            }
            let _ = write!(s, ">{}</td>", c.html);
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody></table></div>\n");
    s
}

/// The colour class of a verdict (claims, tight families, the gate): a verdict may carry a
/// qualifier, e.g. `holds on few instances (14)`.
pub fn verdict_class(verdict: &str) -> &'static str {
    let v = verdict.trim();
    if v.starts_with("holds on few") {
        "warn"
    } else if [
        "holds",
        "tight reproduced",
        "reproduced",
        "upper bound met",
        "passed",
        "improved",
    ]
    .iter()
    .any(|g| v.starts_with(g))
    {
        "good"
    } else if ["violated", "contradicted", "FAIL", "failed"]
        .iter()
        .any(|b| v.starts_with(b))
    {
        "bad"
    } else if ["differs", "untested", "not measured", "worse"]
        .iter()
        .any(|w| v.starts_with(w))
    {
        "warn"
    } else {
        "plain"
    }
}

/// An image from SVG or PNG bytes, as a `data:` URL (never fetched, never scripted).
pub fn data_image(bytes: &[u8], mime: &str, alt: &str, width: Option<u32>) -> String {
    let width = width.map_or(String::new(), |w| format!(r#" width="{w}""#));
    format!(
        r#"<img class="figure" alt="{}"{width} src="data:{mime};base64,{}">"#,
        esc(alt),
        base64(bytes)
    )
}

/// Standard base64 with padding (RFC 4648).
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for (i, shift) in [18, 12, 6, 0].into_iter().enumerate() {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[((n >> shift) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// The whole page: `title`, the table of contents of `sections` (id, heading, body).
pub fn page(title: &str, subtitle: &str, sections: &[(String, String, String)]) -> String {
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src data:; style-src 'unsafe-inline'; script-src 'unsafe-inline'">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{}</title>
<style>{STYLE}</style></head>
<body><header><h1>{}</h1><p class="sub">{}</p><nav>"#,
        esc(title),
        esc(title),
        esc(subtitle)
    );
    for (id, heading, _) in sections {
        let _ = write!(s, r##"<a href="#{}">{}</a> "##, esc(id), esc(heading));
    }
    s.push_str("</nav></header>\n<main>\n");
    for (id, heading, body) in sections {
        let _ = write!(
            s,
            "<section id=\"{}\"><h2>{}</h2>\n{body}</section>\n",
            esc(id),
            esc(heading)
        );
    }
    let _ = write!(
        s,
        "</main><div id=\"tip\" hidden></div><pre id=\"selftest-result\" hidden></pre>\n<script>{SCRIPT}</script></body></html>\n"
    );
    s
}

const STYLE: &str = r#"
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:0;color:#1d2330;background:#fff}
header{background:#1d2a44;color:#fff;padding:14px 24px}
header h1{margin:0;font-size:22px}
header .sub{margin:4px 0 8px;color:#c8d2e6}
nav a{color:#fff;margin-right:12px;font-size:13px;text-decoration:none;border-bottom:1px dotted #9fb0d0}
main{padding:4px 24px 40px;max-width:1500px}
h2{border-bottom:2px solid #1d2a44;padding-bottom:2px;margin-top:30px}
h3{margin:18px 0 6px}
table{border-collapse:collapse;font-size:12.5px}
th,td{border:1px solid #d5d9e2;padding:3px 6px;vertical-align:top;text-align:left}
th{background:#eef1f6;cursor:pointer;white-space:nowrap;position:sticky;top:0}
th.asc::after{content:" \25b2"}th.desc::after{content:" \25bc"}
#claims-table td:nth-child(3){min-width:300px}
#claims-table td:nth-child(1){min-width:110px}
td.num{text-align:right;font-variant-numeric:tabular-nums}
.scroll{max-height:640px;overflow:auto;margin:6px 0}
.good{background:#d8f3dc;color:#14532d;font-weight:600}
.bad{background:#fcd5d5;color:#7f1d1d;font-weight:600}
.warn{background:#fdf1c7;color:#713f12;font-weight:600}
.plain{background:#eef1f6}
.kv{display:grid;grid-template-columns:repeat(3,minmax(0,1fr));gap:2px 18px;font-size:12.5px;margin:6px 0}
.kv div{overflow-wrap:anywhere}.kv b{margin-right:6px}
.figs{display:flex;flex-wrap:wrap;gap:14px;align-items:flex-start}
.fig{border:1px solid #d5d9e2;padding:6px;background:#fafbfd}
.fig p{margin:4px 0 0;font-size:12px;max-width:560px}
img.figure{max-width:560px;height:auto;display:block}
svg.chart{display:block;background:#fff}
svg.chart text{font:11px system-ui,sans-serif;fill:#1d2330}
details{margin:4px 0}
pre{white-space:pre-wrap;font-size:12px;background:#f5f6f9;padding:6px;max-height:360px;overflow:auto}
.note{color:#4a5468;font-size:12.5px}
input.filter{padding:3px 6px;width:280px}
#tip{position:fixed;pointer-events:none;background:#1d2a44;color:#fff;padding:4px 7px;border-radius:3px;font-size:12px;white-space:pre;z-index:9}
"#;

/// Sorting and filtering of tables, the tooltip of chart points, and the self-test that
/// `scripts/report-browser-test.sh` reads from the DOM (`#selftest` in the URL).
const SCRIPT: &str = r#"
(function(){
function key(td){var v=td.getAttribute('data-sort');if(v===null)v=td.textContent.trim();
 var x=parseFloat(v);return (v!==''&&isFinite(x)&&/^[-+]?[0-9.]/.test(v))?[0,x]:[1,v.toLowerCase()];}
function cmp(a,b){if(a[0]!==b[0])return a[0]-b[0];return a[1]<b[1]?-1:a[1]>b[1]?1:0;}
function sortBy(th){var table=th.closest('table'),i=Array.prototype.indexOf.call(th.parentNode.children,th);
 var asc=!th.classList.contains('asc');table.querySelectorAll('th').forEach(function(h){h.classList.remove('asc','desc');});
 th.classList.add(asc?'asc':'desc');var body=table.tBodies[0];var rows=Array.prototype.slice.call(body.rows);
 rows.sort(function(r,s){var c=cmp(key(r.cells[i]),key(s.cells[i]));return asc?c:-c;});rows.forEach(function(r){body.appendChild(r);});}
document.querySelectorAll('table.sortable th').forEach(function(th){th.addEventListener('click',function(){sortBy(th);});});
document.querySelectorAll('input.filter').forEach(function(inp){inp.addEventListener('input',function(){
 var t=document.getElementById(inp.getAttribute('data-table')),q=inp.value.toLowerCase(),n=0;
 Array.prototype.forEach.call(t.tBodies[0].rows,function(r){var show=r.textContent.toLowerCase().indexOf(q)>=0;r.hidden=!show;if(show)n++;});
 var c=document.getElementById(t.id+'-count');if(c)c.textContent=n+' rows';});});
var tip=document.getElementById('tip');
document.addEventListener('mouseover',function(e){var el=e.target;if(!el.closest||!el.closest('svg.chart'))return;
 var t=el.querySelector&&el.querySelector(':scope > title');if(!t){tip.hidden=true;return;}
 tip.textContent=t.textContent;tip.hidden=false;});
document.addEventListener('mousemove',function(e){if(!tip.hidden){tip.style.left=(e.clientX+12)+'px';tip.style.top=(e.clientY+12)+'px';}});
document.addEventListener('mouseout',function(e){if(e.target.closest&&e.target.closest('svg.chart'))tip.hidden=true;});
function selftest(){var out={};document.querySelectorAll('details').forEach(function(d){d.open=true;});var claims=document.getElementById('claims-table');
 out.claim_rows=claims?claims.tBodies[0].rows.length:0;
 out.verdicts=claims?Array.prototype.map.call(claims.tBodies[0].rows,function(r){return r.querySelector('td.verdict').textContent.trim();}):[];
 var imgs=document.querySelectorAll('img'),svgs=document.querySelectorAll('svg.chart'),broken=[];
 imgs.forEach(function(im){if(!im.complete||im.naturalWidth===0||im.getBoundingClientRect().width===0)broken.push(im.alt);});
 svgs.forEach(function(sv){var b=sv.getBoundingClientRect();if(b.width===0||b.height===0||sv.childElementCount===0)broken.push(sv.getAttribute('aria-label'));});
 out.images=imgs.length;out.charts=svgs.length;out.broken=broken;
 out.sort_ok=null;if(claims&&claims.tBodies[0].rows.length>1){var ths=claims.querySelectorAll('th'),j=-1;
  ths.forEach(function(h,k){if(h.textContent==='decided')j=k;});if(j>=0){sortBy(ths[j]);
  var v=Array.prototype.map.call(claims.tBodies[0].rows,function(r){return parseFloat(r.cells[j].textContent);});
  var ok=true;for(var k=1;k<v.length;k++)if(v[k-1]>v[k])ok=false;sortBy(ths[j]);
  var w=Array.prototype.map.call(claims.tBodies[0].rows,function(r){return parseFloat(r.cells[j].textContent);});
  for(k=1;k<w.length;k++)if(w[k-1]<w[k])ok=false;out.sort_ok=ok;}}
 out.resources=performance.getEntriesByType('resource').map(function(e){return e.name;});out.render_ms=Math.round(performance.now());var pre=document.getElementById('selftest-result');
 pre.textContent=JSON.stringify(out);pre.hidden=false;}
if(location.hash==='#selftest'){if(document.readyState==='complete')selftest();else window.addEventListener('load',selftest);}
})();
"#;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc4648_vectors() {
        for (input, want) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(input.as_bytes()), want);
        }
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(
            esc(r#"<script>"a" & 'b'</script>"#),
            "&lt;script&gt;&quot;a&quot; &amp; &#39;b&#39;&lt;/script&gt;"
        );
    }
}
