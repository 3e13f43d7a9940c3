//! The HTML deck: one `<section>` per slide, formulas as MathML, pictures
//! linked relative to the deck, keyboard navigation and one slide per printed
//! page. One file, no network: the only script is inline.

use std::fmt::Write as _;

use anyhow::{Context, Result, bail};
use pulldown_cmark::{Options, Parser, html::push_html};

use super::deck::{Deck, Slide};
use super::math::to_mathml;

/// The words of the deck's frame in one language.
pub struct Words {
    pub title: &'static str,
    pub contents: &'static str,
    pub command: &'static str,
    pub exercise: &'static str,
    pub exercises: &'static str,
    pub keys: &'static str,
}

impl Words {
    pub fn for_lang(lang: &str) -> Words {
        match lang {
            "bg" => Words {
                title: "Лекция 11: стереоскопия и глобално осветление",
                contents: "Съдържание",
                command: "Команда",
                exercise: "Упражнение",
                exercises: "Упражнения",
                keys: "← → PageUp PageDown: смяна на слайда · Home End: първи и последен · Ctrl+P: печат по един слайд на страница",
            },
            _ => Words {
                title: "Lecture 11: stereoscopy and global illumination",
                contents: "Contents",
                command: "Command",
                exercise: "Exercise",
                exercises: "Exercises",
                keys: "← → PageUp PageDown: change slides · Home End: first and last · Ctrl+P: print one slide per page",
            },
        }
    }
}

pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn placeholder(i: usize) -> String {
    format!("MATHQZ{i}ZQ")
}

/// Replaces `$$…$$` and `$…$` (outside code spans) by placeholders that
/// Markdown leaves alone, and returns the formulas converted to MathML.
fn extract_math(md: &str) -> Result<(String, Vec<String>)> {
    let chars: Vec<char> = md.chars().collect();
    let mut text = String::new();
    let mut formulas = Vec::new();
    let mut i = 0;
    let mut in_code = false;
    while i < chars.len() {
        let c = chars[i];
        if c == '`' {
            in_code = !in_code;
        } else if !in_code && c == '\\' && chars.get(i + 1) == Some(&'$') {
            text.push_str("\\$");
            i += 2;
            continue;
        } else if !in_code && c == '$' {
            let display = chars.get(i + 1) == Some(&'$');
            let open = if display { 2 } else { 1 };
            let start = i + open;
            let mut j = start;
            let end = loop {
                if j >= chars.len() {
                    bail!(
                        "a formula opened with `{}` is not closed: `{}`",
                        if display { "$$" } else { "$" },
                        chars[i..].iter().take(60).collect::<String>()
                    );
                }
                if chars[j] == '$' && (!display || chars.get(j + 1) == Some(&'$')) {
                    break j;
                }
                j += 1;
            };
            let tex: String = chars[start..end].iter().collect();
            let ml = to_mathml(tex.trim(), display)?;
            text.push_str(&placeholder(formulas.len()));
            formulas.push(ml);
            i = end + open;
            continue;
        }
        text.push(c);
        i += 1;
    }
    Ok((text, formulas))
}

/// Markdown with formulas to HTML.
pub fn markdown_to_html(md: &str) -> Result<String> {
    let (text, formulas) = extract_math(md)?;
    let mut html = String::new();
    push_html(
        &mut html,
        Parser::new_ext(
            &text,
            Options::ENABLE_TABLES | Options::ENABLE_STRIKETHROUGH,
        ),
    );
    for (i, ml) in formulas.iter().enumerate().rev() {
        let p = placeholder(i);
        let alone = format!("<p>{p}</p>");
        html = if html.contains(&alone) {
            html.replace(&alone, ml)
        } else {
            html.replace(&p, ml)
        };
    }
    Ok(html)
}

fn slide_html(
    out: &mut String,
    slide: &Slide,
    id: usize,
    total: usize,
    words: &Words,
    img_prefix: &str,
) -> Result<()> {
    let body = markdown_to_html(&slide.body).with_context(|| slide.origin.clone())?;
    let _ = write!(
        out,
        "<section class=\"slide\" id=\"s{id}\">\n<h1>{}</h1>\n<div class=\"content\">",
        escape(&slide.title)
    );
    if !body.trim().is_empty() {
        let _ = write!(out, "<div class=\"text\">{body}</div>");
    }
    if !slide.images.is_empty() {
        let many = if slide.images.len() > 2 { " many" } else { "" };
        let _ = write!(out, "<div class=\"figures{many}\">");
        for img in &slide.images {
            let _ = write!(
                out,
                "<figure><img src=\"{p}{src}\" alt=\"{cap}\"><figcaption>{cap}</figcaption></figure>",
                p = img_prefix,
                src = escape(&img.path),
                cap = escape(&img.caption)
            );
        }
        out.push_str("</div>");
    }
    out.push_str("</div>\n<footer>");
    for cmd in &slide.commands {
        let _ = write!(
            out,
            "<span class=\"cmd\">{}: <code>{}</code></span>",
            words.command,
            escape(cmd)
        );
    }
    if !slide.exercises.is_empty() {
        let list: Vec<String> = slide.exercises.iter().map(u32::to_string).collect();
        let label = if list.len() > 1 {
            words.exercises
        } else {
            words.exercise
        };
        let _ = write!(out, "<span class=\"ex\">{label} {}</span>", list.join(", "));
    }
    let _ = writeln!(
        out,
        "<span class=\"num\">{id} / {total}</span></footer>\n</section>"
    );
    Ok(())
}

const STYLE: &str = r#"
html,body{margin:0;background:#1d1f24}
section.slide{box-sizing:border-box;width:100vw;height:100vh;display:flex;flex-direction:column;padding:4vh 5vw 2vh;background:#fdfdfb;color:#16181d;font:2.7vh/1.45 system-ui,"Segoe UI",Roboto,sans-serif;overflow:hidden}
body:not(.js) section.slide{height:auto;min-height:100vh;border-bottom:6px solid #1d1f24}
body.js section.slide{display:none}
body.js section.slide.current{display:flex}
h1{font-size:5.2vh;margin:0 0 2.5vh;color:#173a6a;font-weight:650}
section.cover h1{font-size:6.5vh;margin-top:10vh}
.content{flex:1;display:flex;gap:3vw;min-height:0;align-items:center}
.text{flex:1 1 50%;min-width:0}
.text li{margin:0.6vh 0}
.figures{flex:1 1 50%;display:flex;flex-wrap:wrap;gap:1.5vh 1.5vw;justify-content:center;align-items:flex-start;align-content:center;max-height:100%}
figure{margin:0;text-align:center;flex:0 1 auto;max-width:100%}
figure img{display:block;margin:auto;height:54vh;max-width:100%;object-fit:contain;image-rendering:auto;background:#000}
.figures.many figure{flex:0 1 45%}
.figures.many figure img{height:28vh}
figcaption{font-size:1.9vh;color:#555;margin-top:0.5vh}
math{font-size:1.1em;font-family:"STIX Two Math","Cambria Math","Latin Modern Math","Libertinus Math","Noto Sans Math",math}
math[display=block]{margin:1.6vh 0;font-size:1.2em}
code{font-family:ui-monospace,"DejaVu Sans Mono",Consolas,monospace;font-size:0.92em;background:#eef0f4;padding:0 0.25em;border-radius:3px}
footer{display:flex;flex-wrap:wrap;gap:0.5vh 2.5vw;font-size:1.9vh;color:#555;border-top:1px solid #ccd;padding-top:1vh;margin-top:1.5vh}
footer code{background:none;color:#173a6a}
footer .num{margin-left:auto}
a{color:#1d5fb0}
.keys{color:#777;font-size:1.8vh}
@media print{
 @page{size:landscape;margin:0}
 html,body{background:#fff}
 section.slide,body.js section.slide{display:flex!important;width:100%;height:100vh;break-after:page;page-break-after:always;border:none}
 .keys{display:none}
}
"#;

const SCRIPT: &str = r#"
(function(){
var s=document.querySelectorAll('section.slide'),i=0;
if(!s.length)return;
document.body.classList.add('js');
function find(){var h=location.hash.slice(1);for(var k=0;k<s.length;k++)if(s[k].id===h)return k;return 0;}
function show(n){n=Math.max(0,Math.min(s.length-1,n));s[i].classList.remove('current');i=n;s[i].classList.add('current');
 if(location.hash!=='#'+s[i].id){try{history.replaceState(null,'','#'+s[i].id);}catch(e){}}}
s[0].classList.add('current');show(find());
addEventListener('hashchange',function(){show(find());});
addEventListener('keydown',function(e){if(e.altKey||e.ctrlKey||e.metaKey)return;var k=e.key,n=null;
 if(k==='ArrowRight'||k==='ArrowDown'||k==='PageDown'||k===' '||k==='Enter')n=i+1;
 else if(k==='ArrowLeft'||k==='ArrowUp'||k==='PageUp'||k==='Backspace')n=i-1;
 else if(k==='Home')n=0;else if(k==='End')n=s.length-1;
 if(n!==null){e.preventDefault();show(n);}});
addEventListener('click',function(e){if(e.target.closest('a,code'))return;show(e.clientX>innerWidth/4?i+1:i-1);});
})();
"#;

/// The whole deck as one HTML page; pictures are linked as `img_prefix + path`.
pub fn deck_html(deck: &Deck, img_prefix: &str) -> Result<String> {
    let words = Words::for_lang(&deck.lang);
    let total = deck.slides().count() + 1;
    let mut h = String::new();
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=\"{lang}\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">\
         <title>{title}</title>\n<style>{STYLE}</style></head>\n<body>\n",
        lang = escape(&deck.lang),
        title = escape(words.title)
    );
    // The cover: the title and the chapters, each linked to its first slide.
    let _ = write!(
        h,
        "<section class=\"slide cover\" id=\"s0\">\n<h1>{}</h1>\n<div class=\"content\"><div class=\"text\"><h2>{}</h2><ol>",
        escape(words.title),
        words.contents
    );
    let mut id = 1;
    for chapter in &deck.chapters {
        if let Some(first) = chapter.slides.first() {
            let _ = write!(
                h,
                "<li><a href=\"#s{id}\">{}</a></li>",
                escape(&first.title)
            );
        }
        id += chapter.slides.len();
    }
    let _ = writeln!(
        h,
        "</ol><p class=\"keys\">{}</p></div></div>\n<footer><span class=\"num\">0 / {}</span></footer>\n</section>",
        words.keys,
        total - 1
    );
    for (id, slide) in (1..).zip(deck.slides()) {
        slide_html(&mut h, slide, id, total - 1, &words, img_prefix)?;
    }
    let _ = write!(h, "<script>{SCRIPT}</script>\n</body></html>\n");
    Ok(h)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_become_mathml_and_markdown_leaves_them_alone() {
        let html = markdown_to_html(
            "- the BRDF $f_r(\\mathbf{x}, \\omega_i, \\omega_o)$ and `$HOME`\n\n$$\\int_{\\Omega} f_r \\cos\\Theta_o \\, d\\omega_o \\leq 1$$\n",
        )
        .unwrap();
        assert!(html.contains("<li>the BRDF <math>"), "{html}");
        assert!(html.contains("<code>$HOME</code>"), "{html}");
        assert!(html.contains("<math display=\"block\">"), "{html}");
        assert!(
            !html.contains("<p><math display"),
            "display math is not wrapped: {html}"
        );
        assert!(!html.contains("MATHQZ"), "{html}");
        // Underscores inside formulas must not turn into emphasis.
        assert!(!html.contains("<em>"), "{html}");
    }

    #[test]
    fn unclosed_and_unknown_formulas_are_errors() {
        assert!(
            markdown_to_html("a $x")
                .unwrap_err()
                .to_string()
                .contains("not closed")
        );
        assert!(
            markdown_to_html("$$x")
                .unwrap_err()
                .to_string()
                .contains("$$")
        );
        assert!(
            markdown_to_html("$\\nope$")
                .unwrap_err()
                .to_string()
                .contains("\\nope")
        );
        assert!(markdown_to_html("costs \\$5").is_ok());
    }
}
