//! LaTeX to MathML for the slides: the subset the Lecture 11 deck uses.
//!
//! The rendering equation, BRDFs and Monte Carlo estimators need Greek
//! letters, sub- and superscripts, `\int`, `\sum` and `\prod` with limits,
//! `\frac`, `\sqrt`, accents, `\mathbf`, `\mathrm`, `\mathcal`, `\text`,
//! `\left … \right`, spacing and `\begin{cases}`. Browsers render MathML
//! natively, so the deck needs no script and no network for its formulas.
//!
//! (The `latex2mathml` crate was tried first: it drops the spaces inside
//! `\text{…}` and has no `cases` environment, both of which the slides need.)
//!
//! Anything outside the subset is an error that names the command and where it
//! is, so a typo on a slide fails the build instead of showing raw LaTeX.

use std::fmt::Write as _;

use anyhow::{Result, bail};

use super::symbols::{capital_greek, function, greek, operator};

/// Converts one formula (without its `$` delimiters) to a `<math>` element.
pub fn to_mathml(tex: &str, display: bool) -> Result<String> {
    let mut p = Parser {
        chars: tex.chars().collect(),
        pos: 0,
        display,
    };
    let (items, end) = p.list(Style::Italic)?;
    match end {
        End::Eof => {}
        other => bail!(
            "unexpected {} at character {} of `{tex}`",
            other.describe(),
            p.pos
        ),
    }
    let body = render_row(&items, display);
    Ok(if display {
        format!("<math display=\"block\">{body}</math>")
    } else {
        format!("<math>{body}</math>")
    })
}

/// How letters are drawn.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Style {
    /// Single-letter identifiers in italic (the default of mathematics).
    Italic,
    /// Upright: runs of letters form one identifier (`\mathrm{reflect}`).
    Upright,
    /// Upright bold (`\mathbf{x}`, the lecture's points and normals).
    Bold,
    /// Calligraphic (`\mathcal{P}`, the space of paths).
    Script,
}

/// What ended a list of atoms.
#[derive(Debug, PartialEq)]
enum End {
    Eof,
    RBrace,
    /// `\right` followed by its delimiter (already rendered, maybe empty).
    Right(String),
    Amp,
    NewRow,
    Env(String),
}

impl End {
    fn describe(&self) -> String {
        match self {
            End::Eof => "end of formula".into(),
            End::RBrace => "`}`".into(),
            End::Right(_) => "`\\right`".into(),
            End::Amp => "`&` outside an environment".into(),
            End::NewRow => "`\\\\` outside an environment".into(),
            End::Env(e) => format!("`\\end{{{e}}}`"),
        }
    }
}

/// One atom with its scripts: `base_sub^sup`.
struct Atom {
    base: String,
    sub: Option<String>,
    sup: Option<String>,
    /// Big operator whose limits go under and over it in display style (∑, ∏, max).
    limits: bool,
}

impl Atom {
    fn new(base: String) -> Self {
        Atom {
            base,
            sub: None,
            sup: None,
            limits: false,
        }
    }

    fn render(&self, display: bool) -> String {
        let (under, over) = if self.limits && display {
            ("munder", "mover")
        } else {
            ("msub", "msup")
        };
        let both = if self.limits && display {
            "munderover"
        } else {
            "msubsup"
        };
        match (&self.sub, &self.sup) {
            (None, None) => self.base.clone(),
            (Some(b), None) => format!("<{under}>{}{b}</{under}>", self.base),
            (None, Some(p)) => format!("<{over}>{}{p}</{over}>", self.base),
            (Some(b), Some(p)) => format!("<{both}>{}{b}{p}</{both}>", self.base),
        }
    }
}

/// The atoms as one element (an `<mrow>` unless there is exactly one).
fn render_row(items: &[Atom], display: bool) -> String {
    let inner: String = items.iter().map(|a| a.render(display)).collect();
    if items.len() == 1 && !inner.is_empty() {
        inner
    } else {
        format!("<mrow>{inner}</mrow>")
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn mo(op: &str) -> String {
    format!("<mo>{}</mo>", escape(op))
}

/// An operator that must not grow with the row (plain parentheses beside an integral).
fn mo_fixed(op: &str) -> String {
    format!("<mo stretchy=\"false\">{}</mo>", escape(op))
}

fn mo_fence(op: &str) -> String {
    if op.is_empty() {
        String::new()
    } else {
        format!(
            "<mo fence=\"true\" stretchy=\"true\" symmetric=\"true\">{}</mo>",
            escape(op)
        )
    }
}

fn mspace(em: f32) -> String {
    format!("<mspace width=\"{em}em\"></mspace>")
}

/// The letter in the given style (Unicode mathematical alphanumerics for bold
/// and script: MathML Core draws them without needing `mathvariant`).
fn styled(c: char, style: Style) -> char {
    let shift = |base: u32, from: char| char::from_u32(base + (c as u32 - from as u32));
    match style {
        Style::Bold => match c {
            'A'..='Z' => shift(0x1D400, 'A'),
            'a'..='z' => shift(0x1D41A, 'a'),
            '0'..='9' => shift(0x1D7CE, '0'),
            _ => None,
        }
        .unwrap_or(c),
        Style::Script => match c {
            'B' => 'ℬ',
            'E' => 'ℰ',
            'F' => 'ℱ',
            'H' => 'ℋ',
            'I' => 'ℐ',
            'L' => 'ℒ',
            'M' => 'ℳ',
            'R' => 'ℛ',
            'A'..='Z' => shift(0x1D49C, 'A').unwrap_or(c),
            _ => c,
        },
        Style::Italic | Style::Upright => c,
    }
}

fn mi(text: &str, style: Style) -> String {
    let single = text.chars().count() == 1;
    match style {
        Style::Upright if single => format!("<mi mathvariant=\"normal\">{}</mi>", escape(text)),
        Style::Bold | Style::Script => {
            let t: String = text.chars().map(|c| styled(c, style)).collect();
            format!("<mi mathvariant=\"normal\">{}</mi>", escape(&t))
        }
        _ => format!("<mi>{}</mi>", escape(text)),
    }
}

struct Parser {
    chars: Vec<char>,
    pos: usize,
    display: bool,
}

impl Parser {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }

    fn skip_ws(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.pos += 1;
        }
    }

    fn context(&self) -> String {
        self.chars.iter().collect()
    }

    /// Reads a command name after `\`: letters, or one other character.
    fn command_name(&mut self) -> Result<String> {
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
            self.pos += 1;
        }
        if self.pos == start {
            match self.peek() {
                Some(c) => {
                    self.pos += 1;
                    return Ok(c.to_string());
                }
                None => bail!("a lone `\\` at the end of `{}`", self.context()),
            }
        }
        Ok(self.chars[start..self.pos].iter().collect())
    }

    /// Reads `{raw text}` verbatim (for `\text` and environment names).
    fn raw_group(&mut self) -> Result<String> {
        self.skip_ws();
        if self.peek() != Some('{') {
            bail!(
                "expected `{{` at character {} of `{}`",
                self.pos,
                self.context()
            );
        }
        self.pos += 1;
        let mut depth = 0;
        let start = self.pos;
        while let Some(c) = self.peek() {
            match c {
                '{' => depth += 1,
                '}' if depth == 0 => {
                    let s = self.chars[start..self.pos].iter().collect();
                    self.pos += 1;
                    return Ok(s);
                }
                '}' => depth -= 1,
                _ => {}
            }
            self.pos += 1;
        }
        bail!("a `{{` without its `}}` in `{}`", self.context())
    }

    /// One argument: a `{group}` or a single token.
    fn argument(&mut self, style: Style) -> Result<String> {
        self.skip_ws();
        match self.peek() {
            None => bail!(
                "a command or script lacks its argument in `{}`",
                self.context()
            ),
            Some('{') => {
                self.pos += 1;
                let (items, end) = self.list(style)?;
                if end != End::RBrace {
                    bail!("a `{{` without its `}}` in `{}`", self.context());
                }
                Ok(render_row(&items, self.display))
            }
            Some(_) => {
                let atom = self.atom(style, true)?;
                match atom {
                    Some(a) => Ok(a.base),
                    None => bail!(
                        "expected an argument at character {} of `{}`",
                        self.pos,
                        self.context()
                    ),
                }
            }
        }
    }

    /// Parses atoms until `}`, `&`, `\\`, `\right`, `\end{…}` or the end.
    fn list(&mut self, style: Style) -> Result<(Vec<Atom>, End)> {
        let mut items: Vec<Atom> = Vec::new();
        loop {
            self.skip_ws();
            let Some(c) = self.peek() else {
                return Ok((items, End::Eof));
            };
            match c {
                '}' => {
                    self.pos += 1;
                    return Ok((items, End::RBrace));
                }
                '&' => {
                    self.pos += 1;
                    return Ok((items, End::Amp));
                }
                '_' | '^' | '\'' => {
                    self.pos += 1;
                    let Some(last) = items.last_mut() else {
                        bail!(
                            "`{c}` has nothing to attach to at character {} of `{}`",
                            self.pos,
                            self.context()
                        );
                    };
                    if c == '\'' {
                        // A prime is a glyph of its own beside the base (x′): as a
                        // superscript it would be raised twice.
                        let base = std::mem::take(&mut last.base);
                        last.base = format!(
                            "<mrow>{base}<mo form=\"postfix\" lspace=\"0\" rspace=\"0\">′</mo></mrow>"
                        );
                        continue;
                    }
                    let script = self.argument(style)?;
                    let slot = if c == '_' {
                        &mut last.sub
                    } else {
                        &mut last.sup
                    };
                    match slot {
                        Some(_) => bail!(
                            "a double `{c}` at character {} of `{}`: group with braces",
                            self.pos,
                            self.context()
                        ),
                        None => *slot = Some(script),
                    }
                }
                '\\' => {
                    let save = self.pos;
                    self.pos += 1;
                    let name = self.command_name()?;
                    match name.as_str() {
                        "\\" => return Ok((items, End::NewRow)),
                        "right" => {
                            let delim = self.delimiter()?;
                            return Ok((items, End::Right(delim)));
                        }
                        "end" => {
                            let env = self.raw_group()?;
                            return Ok((items, End::Env(env)));
                        }
                        _ => {
                            self.pos = save;
                            if let Some(a) = self.atom(style, false)? {
                                items.push(a);
                            }
                        }
                    }
                }
                _ => {
                    if let Some(mut a) = self.atom(style, false)? {
                        // A minus after an operator or at the start is a sign, not a
                        // subtraction: `(−ω_i · n)` must not get binary spacing.
                        let after_operator = items.last().is_none_or(|p| {
                            p.base.starts_with("<mo") && p.sub.is_none() && p.sup.is_none()
                        });
                        if a.base == "<mo>−</mo>" && after_operator {
                            a.base = "<mo form=\"prefix\">−</mo>".into();
                        }
                        items.push(a);
                    }
                }
            }
        }
    }

    /// The delimiter after `\left` or `\right` (`.` = none).
    fn delimiter(&mut self) -> Result<String> {
        self.skip_ws();
        match self.peek() {
            Some('\\') => {
                self.pos += 1;
                let name = self.command_name()?;
                match operator(&name) {
                    Some(op) => Ok(op.to_string()),
                    None => bail!(
                        "`\\{name}` is not a delimiter for \\left or \\right in `{}`",
                        self.context()
                    ),
                }
            }
            Some('.') => {
                self.pos += 1;
                Ok(String::new())
            }
            Some(c) if "()[]|".contains(c) => {
                self.pos += 1;
                Ok(c.to_string())
            }
            _ => bail!(
                "\\left and \\right need a delimiter ( ) [ ] | \\{{ \\}} or . in `{}`",
                self.context()
            ),
        }
    }

    /// One atom (without scripts). `single` reads one digit, not a number.
    fn atom(&mut self, style: Style, single: bool) -> Result<Option<Atom>> {
        self.skip_ws();
        let Some(c) = self.peek() else {
            return Ok(None);
        };
        self.pos += 1;
        let ml = match c {
            '{' => {
                let (items, end) = self.list(style)?;
                if end != End::RBrace {
                    bail!("a `{{` without its `}}` in `{}`", self.context());
                }
                render_row(&items, self.display)
            }
            '\\' => return self.command(style).map(Some),
            '0'..='9' => {
                let start = self.pos - 1;
                if !single {
                    while self.peek().is_some_and(|d| d.is_ascii_digit() || d == '.') {
                        self.pos += 1;
                    }
                    // A trailing full stop ends the sentence, not the number.
                    if self.chars[self.pos - 1] == '.' {
                        self.pos -= 1;
                    }
                }
                let num: String = self.chars[start..self.pos]
                    .iter()
                    .map(|&d| styled(d, style))
                    .collect();
                format!("<mn>{num}</mn>")
            }
            '-' => mo("−"),
            '(' | ')' | '[' | ']' | '|' => mo_fixed(&c.to_string()),
            '~' => mspace(0.25),
            c if c.is_alphabetic() => {
                if style == Style::Upright && !single {
                    let start = self.pos - 1;
                    while self.peek().is_some_and(char::is_alphabetic) {
                        self.pos += 1;
                    }
                    let word: String = self.chars[start..self.pos].iter().collect();
                    mi(&word, style)
                } else {
                    mi(&c.to_string(), style)
                }
            }
            c if "+=<>,;:/*!.?".contains(c) || !c.is_ascii() => mo(&c.to_string()),
            '}' | '&' | '_' | '^' => bail!(
                "unexpected `{c}` at character {} of `{}`",
                self.pos,
                self.context()
            ),
            c => bail!(
                "the character `{c}` is not supported in formulas (in `{}`)",
                self.context()
            ),
        };
        Ok(Some(Atom::new(ml)))
    }

    /// A command after its `\`.
    fn command(&mut self, style: Style) -> Result<Atom> {
        let name = self.command_name()?;
        let n = name.as_str();
        if let Some(g) = greek(n) {
            return Ok(Atom::new(mi(&g.to_string(), style)));
        }
        if let Some(g) = capital_greek(n) {
            return Ok(Atom::new(mi(&g.to_string(), Style::Upright)));
        }
        if let Some(op) = operator(n) {
            let ml = if op == "‖" || op == "{" || op == "}" || op == "⟨" || op == "⟩" {
                mo_fixed(op)
            } else {
                mo(op)
            };
            return Ok(Atom::new(ml));
        }
        if let Some((f, limits)) = function(n) {
            let mut a = Atom::new(format!("<mi>{f}</mi>"));
            a.limits = limits;
            return Ok(a);
        }
        let atom = match n {
            "infty" => Atom::new(mi("∞", Style::Upright)),
            "partial" => Atom::new(mi("∂", Style::Upright)),
            "int" | "iint" | "oint" => {
                let sym = match n {
                    "int" => "∫",
                    "iint" => "∬",
                    _ => "∮",
                };
                Atom::new(format!("<mo largeop=\"true\">{sym}</mo>"))
            }
            "sum" | "prod" => {
                let mut a = Atom::new(format!(
                    "<mo largeop=\"true\" movablelimits=\"true\">{}</mo>",
                    if n == "sum" { "∑" } else { "∏" }
                ));
                a.limits = true;
                a
            }
            "," => Atom::new(mspace(0.1667)),
            ":" | ">" => Atom::new(mspace(0.2222)),
            ";" => Atom::new(mspace(0.2778)),
            " " => Atom::new(mspace(0.25)),
            "quad" => Atom::new(mspace(1.0)),
            "qquad" => Atom::new(mspace(2.0)),
            "!" => Atom::new(String::new()),
            "frac" | "dfrac" | "tfrac" => {
                let num = self.argument(style)?;
                let den = self.argument(style)?;
                Atom::new(format!("<mfrac>{num}{den}</mfrac>"))
            }
            "sqrt" => {
                let arg = self.argument(style)?;
                Atom::new(format!("<msqrt>{arg}</msqrt>"))
            }
            "hat" | "bar" | "tilde" | "vec" | "overline" => {
                let arg = self.argument(style)?;
                let accent = match n {
                    "hat" => "^",
                    "bar" | "overline" => "¯",
                    "tilde" => "~",
                    _ => "→",
                };
                Atom::new(format!(
                    "<mover accent=\"true\">{arg}<mo stretchy=\"false\">{accent}</mo></mover>"
                ))
            }
            "mathbf" | "boldsymbol" | "bm" => Atom::new(self.argument(Style::Bold)?),
            "mathrm" | "operatorname" | "mathit" => {
                let s = if n == "mathit" {
                    Style::Italic
                } else {
                    Style::Upright
                };
                Atom::new(self.argument(s)?)
            }
            "mathcal" => Atom::new(self.argument(Style::Script)?),
            "text" | "textrm" | "mbox" => {
                let raw = self.raw_group()?;
                // Token elements trim their spaces: keep them as no-break spaces.
                Atom::new(format!(
                    "<mtext>{}</mtext>",
                    escape(&raw.replace(' ', "\u{a0}"))
                ))
            }
            "left" => {
                let open = self.delimiter()?;
                let (items, end) = self.list(style)?;
                let End::Right(close) = end else {
                    bail!("`\\left` without `\\right` in `{}`", self.context());
                };
                Atom::new(format!(
                    "<mrow>{}{}{}</mrow>",
                    mo_fence(&open),
                    render_row(&items, self.display),
                    mo_fence(&close)
                ))
            }
            "begin" => {
                let env = self.raw_group()?;
                Atom::new(self.environment(&env, style)?)
            }
            _ => bail!(
                "unknown command `\\{n}` in `{}` (the slides' LaTeX subset: see commands/slides/math.rs)",
                self.context()
            ),
        };
        Ok(atom)
    }

    /// `\begin{env} a & b \\ c & d \end{env}` for cases and matrices.
    fn environment(&mut self, env: &str, style: Style) -> Result<String> {
        let (open, close, align) = match env {
            "cases" => ("{", "", "left"),
            "matrix" => ("", "", "center"),
            "pmatrix" => ("(", ")", "center"),
            "bmatrix" => ("[", "]", "center"),
            _ => bail!(
                "unknown environment `{env}` in `{}` (cases, matrix, pmatrix, bmatrix)",
                self.context()
            ),
        };
        let mut table = String::new();
        let mut row = String::new();
        loop {
            let (items, end) = self.list(style)?;
            let _ = write!(
                row,
                "<mtd style=\"text-align:{align}\">{}</mtd>",
                render_row(&items, self.display)
            );
            match end {
                End::Amp => {}
                End::NewRow => {
                    let _ = write!(table, "<mtr>{row}</mtr>");
                    row.clear();
                }
                End::Env(e) if e == env => {
                    if !row.is_empty() {
                        let _ = write!(table, "<mtr>{row}</mtr>");
                    }
                    break;
                }
                other => bail!(
                    "`\\begin{{{env}}}` ended by {} in `{}`",
                    other.describe(),
                    self.context()
                ),
            }
        }
        Ok(format!(
            "<mrow>{}<mtable columnalign=\"{align}\">{table}</mtable>{}</mrow>",
            mo_fence(open),
            mo_fence(close)
        ))
    }
}
