//! Query strings (`?scene=cornell&spp=64`): read, percent-decoded and
//! checked, with a one-line reason for anything wrong.

use std::collections::BTreeMap;
use std::str::FromStr;

/// The longest query string the lab reads (its forms are short).
const MAX_QUERY: usize = 4096;

/// The parameters of one request: each name at most once.
#[derive(Debug, Default)]
pub struct Query {
    params: BTreeMap<String, String>,
}

impl Query {
    /// Reads `a=1&b=two%20words`; `+` is a space. A name given twice, a
    /// name that is not in `allowed`, or bytes that are not UTF-8 are errors.
    pub fn parse(query: &str, allowed: &[&str]) -> Result<Query, String> {
        if query.len() > MAX_QUERY {
            return Err(format!(
                "the query string is {} bytes long, more than the {MAX_QUERY} the lab reads",
                query.len()
            ));
        }
        let mut params = BTreeMap::new();
        for pair in query.split('&').filter(|p| !p.is_empty()) {
            let (name, value) = pair.split_once('=').unwrap_or((pair, ""));
            let (name, value) = (decode(name)?, decode(value)?);
            if !allowed.contains(&name.as_str()) {
                return Err(format!(
                    "unknown parameter `{name}`: this address takes {}",
                    allowed.join(", ")
                ));
            }
            if params.insert(name.clone(), value).is_some() {
                return Err(format!("the parameter `{name}` is given twice"));
            }
        }
        Ok(Query { params })
    }

    /// The value of `name`, if given.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.params.get(name).map(String::as_str)
    }

    /// Every parameter, in name order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &str)> {
        self.params.iter().map(|(k, v)| (k.as_str(), v.as_str()))
    }

    /// `name` as a `T`, or `default` if it is not given.
    pub fn number<T: FromStr + Copy>(&self, name: &str, default: T) -> Result<T, String> {
        match self.get(name) {
            None => Ok(default),
            Some(v) => v
                .trim()
                .parse()
                .map_err(|_| format!("`{name}` must be a number, got {v:?}")),
        }
    }

    /// `name` as a finite number in `range` (`default` if not given).
    pub fn in_range(
        &self,
        name: &str,
        default: f32,
        range: std::ops::RangeInclusive<f32>,
    ) -> Result<f32, String> {
        let v: f32 = self.number(name, default)?;
        if !v.is_finite() || !range.contains(&v) {
            return Err(format!(
                "`{name}` must be in [{}, {}], got {v}",
                range.start(),
                range.end()
            ));
        }
        Ok(v)
    }

    /// `name` as a yes/no (`1`, `true`, `on` or `0`, `false`, `off`).
    pub fn flag(&self, name: &str) -> Result<bool, String> {
        match self.get(name) {
            None => Ok(false),
            Some("1" | "true" | "on" | "yes" | "") => Ok(true),
            Some("0" | "false" | "off" | "no") => Ok(false),
            Some(v) => Err(format!("`{name}` must be 1 or 0, got {v:?}")),
        }
    }

    /// The page's id (`page=…`): 1 to 64 letters, digits, `-` or `_`.
    pub fn page(&self) -> Result<&str, String> {
        let id = self
            .get("page")
            .ok_or("the parameter `page` is missing (the page's id)")?;
        let ok = (1..=64).contains(&id.len())
            && id
                .bytes()
                .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_');
        if ok {
            Ok(id)
        } else {
            Err(format!(
                "`page` must be 1 to 64 letters, digits, - or _, got {id:?}"
            ))
        }
    }
}

/// Percent-decoding (`%20` and `+` are spaces).
fn decode(s: &str) -> Result<String, String> {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' => {
                let hex = bytes
                    .get(i + 1..i + 3)
                    .and_then(|h| std::str::from_utf8(h).ok())
                    .and_then(|h| u8::from_str_radix(h, 16).ok())
                    .ok_or_else(|| format!("a broken %-escape in {s:?}"))?;
                out.push(hex);
                i += 2;
            }
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8(out).map_err(|_| format!("{s:?} is not UTF-8 once decoded"))
}
