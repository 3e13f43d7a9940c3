//! The HTML deck: one `<section>` per slide, formulas as MathML, pictures
//! linked relative to the deck, keyboard navigation and one slide per printed
//! page. One file, no network: the only script is inline.
//!
//! Every slide must fit the screen. The pictures share the space left by the
//! text (a grid whose cells shrink, each picture scaled to fit its cell), and
//! the deck measures itself: opened with `#check` (`index.html#check`), the
//! script shows every slide in turn, finds each element that runs off the
//! slide, overlaps the title or the footer, is cut off or squeezed too small,
//! and writes the list into `<pre id="overflow">`, which headless Chromium's
//! `--dump-dom` reads (see `lessons/lesson11/tests/slides.rs`).
//!
//! A drawing written by hand into the Markdown as raw HTML,
//! `<figure class="drawing"><svg …>…</svg><figcaption>…</figcaption></figure>`
//! (no blank line inside), is laid out with the pictures. A picture that the
//! chapters do not render yet (listed in `slides/NEEDED-PICTURES.md`) shows as
//! a dashed placeholder naming its file.

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
    /// Shown in place of a picture that is not rendered yet.
    pub missing: &'static str,
}

impl Words {
    pub fn for_lang(lang: &str) -> Words {
        match lang {
            "bg" => Words {
                title: "Лекция 11: стереоскопия и глобално осветление",
                contents: "Съдържание",
                command: "Команда",
                exercise: "Задача",
                exercises: "Задачи",
                keys: "← → PageUp PageDown: смяна на слайда · Home End: първи и последен · Ctrl+P: печат по един слайд на страница",
                missing: "картината още не е рендерирана",
            },
            _ => Words {
                title: "Lecture 11: stereoscopy and global illumination",
                contents: "Contents",
                command: "Command",
                exercise: "Exercise",
                exercises: "Exercises",
                keys: "← → PageUp PageDown: change slides · Home End: first and last · Ctrl+P: print one slide per page",
                missing: "not rendered yet",
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

/// Takes the hand-drawn figures (`<figure class="drawing">…</figure>`, raw
/// HTML in the Markdown) out of a slide's HTML, so that they are laid out with
/// the pictures; returns the rest and the drawings.
pub fn take_drawings(html: &str) -> Result<(String, Vec<String>)> {
    const OPEN: &str = "<figure class=\"drawing\"";
    const CLOSE: &str = "</figure>";
    let mut rest = String::new();
    let mut drawings = Vec::new();
    let mut s = html;
    while let Some(start) = s.find(OPEN) {
        rest.push_str(&s[..start]);
        let Some(len) = s[start..].find(CLOSE) else {
            bail!(
                "a <figure class=\"drawing\"> is not closed by </figure> (keep it free of blank lines)"
            );
        };
        let end = start + len + CLOSE.len();
        drawings.push(s[start..end].to_string());
        s = &s[end..];
    }
    rest.push_str(s);
    Ok((rest, drawings))
}

fn slide_html(
    out: &mut String,
    slide: &Slide,
    id: usize,
    total: usize,
    words: &Words,
    lang: &str,
    img_prefix: &str,
) -> Result<()> {
    let body = markdown_to_html(&slide.body).with_context(|| slide.origin.clone())?;
    let (body, drawings) = take_drawings(&body).with_context(|| slide.origin.clone())?;
    let figures = slide.images.len() + drawings.len();
    // One figure sits beside the text; several go in a row under it.
    let layout = if figures > 1 { " stack" } else { "" };
    let _ = write!(
        out,
        "<section class=\"slide\" id=\"s{id}\">\n<h1>{}</h1>\n<div class=\"content{layout}\">",
        escape(&slide.title)
    );
    if !body.trim().is_empty() {
        let _ = write!(out, "<div class=\"text\">{body}</div>");
    }
    if figures > 0 {
        let _ = write!(out, "<div class=\"figures\" style=\"--cols:{figures}\">");
        for d in &drawings {
            out.push_str(d);
        }
        for img in &slide.images {
            let _ = write!(
                out,
                "<figure data-missing=\"{missing}: {src}\"><img src=\"{p}{src}\" alt=\"{cap}\" \
                 onerror=\"this.parentNode.classList.add('missing')\"><figcaption>{cap}</figcaption></figure>",
                p = img_prefix,
                src = escape(&img.file(lang)),
                cap = escape(&img.caption),
                missing = escape(words.missing),
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

/// Sizes follow the smaller of the screen's height and width, so that a 4:3
/// screen gets the same lines as a 16:9 one.
const STYLE: &str = r#"
:root{--fs:min(2.6vh,1.55vw)}
html,body{margin:0;background:#1d1f24}
section.slide{box-sizing:border-box;width:100vw;height:100vh;display:flex;flex-direction:column;padding:3.2vh 4.5vw 1.8vh;background:#fdfdfb;color:#16181d;font:var(--fs)/1.42 system-ui,"Segoe UI",Roboto,sans-serif;overflow:hidden}
body:not(.js) section.slide{height:auto;min-height:100vh;border-bottom:6px solid #1d1f24}
body.js section.slide{display:none}
body.js section.slide.current{display:flex}
h1{flex:none;font-size:calc(1.85*var(--fs));line-height:1.2;margin:0 0 1.4vh;color:#173a6a;font-weight:650}
section.cover h1{font-size:calc(2.3*var(--fs));margin-top:8vh}
h2{font-size:calc(1.3*var(--fs));margin:0.5em 0}
.content{flex:1 1 0;min-height:0;display:flex;gap:1.5vh 2.5vw;align-items:stretch}
.content.stack{flex-direction:column}
.text{flex:1 1 0;min-width:0;align-self:center}
.content.stack .text{flex:none;align-self:stretch}
.text p{margin:0.5em 0}
.text ul,.text ol{margin:0.3em 0;padding-left:1.3em}
.text li{margin:0.35em 0}
.text li li{margin:0.15em 0}
.text blockquote{display:inline-block;margin:0 0 0.4em;padding:0.1em 0.7em;border-radius:0.5em;background:#fff1cf;color:#6b4300;font-size:0.82em}
.text blockquote p{margin:0}
.text table{border-collapse:collapse;font-size:0.85em;margin:0.5em 0}
.text th,.text td{padding:0.15em 0.7em;border-bottom:1px solid #d4d7e0;text-align:right}
.text th{color:#173a6a;font-weight:600;border-bottom:2px solid #aab}
.text th:first-child,.text td:first-child{text-align:left}
.figures{flex:1 1 0;min-width:0;min-height:0;display:grid;grid-template-columns:repeat(var(--cols,1),minmax(0,1fr));grid-template-rows:minmax(0,1fr);gap:1vh 1.5vw}
figure{margin:0;min-width:0;min-height:0;display:flex;flex-direction:column;align-items:center}
figure>img,figure>svg{display:block;flex:1 1 0;min-height:0;width:100%;object-fit:contain;object-position:50% 100%}
figcaption{flex:none;font-size:calc(0.7*var(--fs));line-height:1.25;color:#555;margin-top:0.5vh;text-align:center}
figure.missing{border:2px dashed #b8bccc;border-radius:6px}
figure.missing img{display:none}
figure.missing::before{content:attr(data-missing);flex:1 1 0;min-height:0;display:flex;align-items:center;justify-content:center;padding:0.5em;color:#778;font-size:calc(0.7*var(--fs));text-align:center;overflow-wrap:anywhere}
math{font-size:1.05em;font-family:"STIX Two Math","Cambria Math","Latin Modern Math","Libertinus Math","Noto Sans Math",math}
math[display=block]{margin:0.9vh 0;font-size:1.12em}
code{font-family:ui-monospace,"DejaVu Sans Mono",Consolas,monospace;font-size:0.9em;background:#eef0f4;padding:0 0.25em;border-radius:3px}
footer{flex:none;display:flex;flex-wrap:wrap;gap:0.3vh 2.5vw;font-size:calc(0.7*var(--fs));color:#555;border-top:1px solid #ccd;padding-top:0.8vh;margin-top:1.2vh}
footer code{background:none;color:#173a6a;overflow-wrap:anywhere}
footer .num{margin-left:auto}
a{color:#1d5fb0}
.keys{color:#777;font-size:calc(0.7*var(--fs))}
#overflow{position:fixed;top:0;left:0;right:0;margin:0;max-height:50vh;overflow:auto;padding:1em;background:#fffbe6;color:#000;font:13px/1.4 ui-monospace,monospace;white-space:pre-wrap;z-index:9}
@media print{
 @page{size:landscape;margin:0}
 html,body{background:#fff}
 section.slide,body.js section.slide{display:flex!important;width:100%;height:100vh;break-after:page;page-break-after:always;border:none}
 .keys,#overflow{display:none}
}
"#;

/// Navigation, and the `#check` mode that measures every slide.
const SCRIPT: &str = r#"
(function(){
var s=document.querySelectorAll('section.slide'),i=0;
if(!s.length)return;
var sizes=location.hash==='#check-sizes',checking=location.hash==='#check'||sizes;
document.body.classList.add('js');
function find(){var h=location.hash.slice(1);for(var k=0;k<s.length;k++)if(s[k].id===h)return k;return 0;}
function show(n){n=Math.max(0,Math.min(s.length-1,n));s[i].classList.remove('current');i=n;s[i].classList.add('current');
 if(!checking&&location.hash!=='#'+s[i].id){try{history.replaceState(null,'','#'+s[i].id);}catch(e){}}}
s[0].classList.add('current');show(find());
addEventListener('hashchange',function(){show(find());});
addEventListener('keydown',function(e){if(e.altKey||e.ctrlKey||e.metaKey)return;var k=e.key,n=null;
 if(k==='ArrowRight'||k==='ArrowDown'||k==='PageDown'||k===' '||k==='Enter')n=i+1;
 else if(k==='ArrowLeft'||k==='ArrowUp'||k==='PageUp'||k==='Backspace')n=i-1;
 else if(k==='Home')n=0;else if(k==='End')n=s.length-1;
 if(n!==null){e.preventDefault();show(n);}});
addEventListener('click',function(e){if(e.target.closest('a,code,#overflow'))return;show(e.clientX>innerWidth/4?i+1:i-1);});
function describe(el){var t=el.tagName.toLowerCase();
 if(t==='img')return 'picture '+el.getAttribute('src').replace(/^.*img\//,'');
 if(t==='figure'&&el.dataset.missing)return 'placeholder of '+el.dataset.missing.replace(/^.*: /,'');
 var x=(el.textContent||'').replace(/\s+/g,' ').trim();return t+(x?' \u201c'+x.slice(0,48)+(x.length>48?'\u2026':'')+'\u201d':'');}
function shown(el,r){if(el.tagName.toLowerCase()!=='img'||!el.naturalWidth)return r;
 var k=Math.min(r.width/el.naturalWidth,r.height/el.naturalHeight);return {width:el.naturalWidth*k,height:el.naturalHeight*k};}
function measure(sec){var b=sec.getBoundingClientRect(),h=sec.querySelector('h1').getBoundingClientRect(),f=sec.querySelector('footer').getBoundingClientRect(),bad=[],seen=[];
 function off(r){return r.right>b.right+1||r.left<b.left-1||r.bottom>b.bottom+1||r.top<b.top-1;}
 function add(el,why){for(var k=0;k<seen.length;k++)if(seen[k].contains(el))return;seen.push(el);bad.push(describe(el)+' '+why);}
 var figs=[].map.call(sec.querySelectorAll('.content .figures'),function(e){return e.getBoundingClientRect();});
 function onpicture(r){for(var q=0;q<figs.length;q++){var g=figs[q];if(r.left<g.right-1&&r.right>g.left+1&&r.top<g.bottom-1&&r.bottom>g.top+1)return true;}return false;}
 if(off(h))add(sec.querySelector('h1'),'runs off the slide');
 if(off(f))add(sec.querySelector('footer'),'runs off the slide');
 var all=sec.querySelectorAll('.content *, footer *');
 for(var k=0;k<all.length;k++){var el=all[k],t=el.tagName.toLowerCase();
  if(el.closest('svg')&&t!=='svg')continue;
  var r=el.getBoundingClientRect();if(!r.width&&!r.height)continue;
  if(!el.closest('footer')){
   if(r.bottom>f.top+1){add(el,'overlaps the footer ('+Math.round(r.bottom-f.top)+' px)');continue;}
   if(r.top<h.bottom-1){add(el,'overlaps the title ('+Math.round(h.bottom-r.top)+' px)');continue;}}
  if(off(r)){add(el,'runs off the slide');continue;}
  if(!el.closest('.figures,footer')&&!el.querySelector('.figures')&&onpicture(r)){add(el,'runs into the picture');continue;}
  if(/^(p|li|td|th|figcaption|h2|blockquote|code|span)$/.test(t)&&el.scrollWidth>el.clientWidth+1&&getComputedStyle(el).display!=='inline'){add(el,'is cut off');continue;}
  if((t==='img'||t==='svg')&&el.closest('.figures')){var d=shown(el,r);
   if(d.height<0.15*innerHeight||d.width<0.1*innerWidth)add(el,'is squeezed to '+Math.round(d.width)+'\u00d7'+Math.round(d.height)+' px');
   else if(sizes&&t==='img'&&/\.png$/.test(el.getAttribute('src'))&&(el.naturalWidth<256||d.width>2*el.naturalWidth))add(el,'is '+el.naturalWidth+' px wide, shown at '+Math.round(d.width)+' px');}}
 return bad;}
function check(){var lines=[],n=0,keep=i;
 for(var k=0;k<s.length;k++){show(k);var bad=measure(s[k]);if(bad.length){n++;
  lines.push(s[k].id+' \u201c'+s[k].querySelector('h1').textContent+'\u201d: '+bad.join('; '));}}
 show(keep);
 var pre=document.getElementById('overflow')||document.body.appendChild(document.createElement('pre'));pre.id='overflow';
 pre.textContent='checked '+s.length+' slides at '+innerWidth+'x'+innerHeight+': '+n+' do not fit\n'+lines.join('\n');}
if(checking)addEventListener('load',check);
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
        slide_html(&mut h, slide, id, total - 1, &words, &deck.lang, img_prefix)?;
    }
    let _ = write!(h, "<script>{SCRIPT}</script>\n</body></html>\n");
    Ok(h)
}
