//! The scene file format: what a TOML scene file may contain, as serde types.
//!
//! Lecture topic: the scenes of the lecture's pictures. The format is
//! documented field by field, with an example, in `raytracer/scenes/README.md`.
//!
//! These types only describe the text: every table denies unknown fields (so
//! a typo such as `radiuss` is an error, not a silently ignored line), every
//! number must be finite, and values checked after parsing are wrapped in
//! [`Spanned`] so that the loader ([`super::load`]) can point at their line.
//! Shapes, materials and lights are flat tables with a `type` key and optional
//! fields, not serde's tagged enums: tagged enums buffer their content and
//! lose the positions needed for precise errors.

use std::collections::BTreeMap;
use std::fmt;

use serde::Deserialize;
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use toml::Spanned;

use crate::math::{Color, Vec3};

/// A whole scene file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    pub camera: Spanned<CameraDesc>,
    #[serde(default)]
    pub render: RenderDesc,
    /// Materials by name (keys keep their position for file-order sorting).
    #[serde(default)]
    pub materials: BTreeMap<Spanned<String>, Spanned<MaterialDesc>>,
    #[serde(default)]
    pub shapes: Vec<Spanned<ShapeDesc>>,
    #[serde(default)]
    pub lights: Vec<Spanned<LightDesc>>,
    pub environment: Option<Spanned<EnvironmentDesc>>,
}

/// `[camera]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraDesc {
    pub position: Spanned<Vec3Desc>,
    pub look_at: Spanned<Vec3Desc>,
    /// Default `[0, 1, 0]`.
    pub up: Option<Spanned<Vec3Desc>>,
    /// Vertical field of view in degrees.
    pub fov: Spanned<Real>,
    /// Lens radius; default 0 (pinhole).
    pub aperture_radius: Option<Spanned<Real>>,
    /// Default: the distance from `position` to `look_at`.
    pub focus_distance: Option<Spanned<Real>>,
}

/// `[render]`: every field optional, defaults from [`super::RenderSettings`].
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderDesc {
    pub width: Option<Spanned<u32>>,
    pub height: Option<Spanned<u32>>,
    pub spp: Option<Spanned<u32>>,
    /// Mitsuba's convention; -1 = unlimited.
    pub max_depth: Option<Spanned<i64>>,
    pub rr_depth: Option<Spanned<u32>>,
    pub seed: Option<Spanned<u64>>,
}

/// `[materials.NAME]`: `type` is lambert, phong, mirror or glass.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialDesc {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    /// lambert (colour or texture), phong (colour).
    pub albedo: Option<Spanned<TextureDesc>>,
    /// phong.
    pub exponent: Option<Spanned<Real>>,
    /// mirror; default 1.
    pub reflectance: Option<Spanned<ColorDesc>>,
    /// glass; default 1.5.
    pub ior: Option<Spanned<Real>>,
    /// glass; default 1.
    pub tint: Option<Spanned<ColorDesc>>,
    /// lambert, phong, mirror: "both" (default) or "front" (black from behind).
    pub sides: Option<Spanned<String>>,
}

/// `[[shapes]]`: `type` is sphere, quad, rectangle, cube or mesh.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShapeDesc {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    /// Optional name shown in statistics and debugging.
    pub name: Option<String>,
    pub material: Spanned<String>,
    /// Emitted radiance: the shape becomes an area light.
    pub emission: Option<Spanned<ColorDesc>>,
    /// Emit on both sides (default: only on the side of the normal).
    pub two_sided: Option<Spanned<bool>>,
    /// sphere.
    pub center: Option<Spanned<Vec3Desc>>,
    pub radius: Option<Spanned<Real>>,
    /// quad.
    pub origin: Option<Spanned<Vec3Desc>>,
    pub edge1: Option<Spanned<Vec3Desc>>,
    pub edge2: Option<Spanned<Vec3Desc>>,
    /// mesh: an OBJ file, relative to the scene file.
    pub file: Option<Spanned<String>>,
    /// rectangle, cube, mesh: `translate · rotate · scale` (scale first).
    pub translate: Option<Spanned<Vec3Desc>>,
    pub rotate: Option<Spanned<RotateDesc>>,
    pub scale: Option<Spanned<ScaleDesc>>,
}

/// `[[lights]]`: `type` is point.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightDesc {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    pub position: Option<Spanned<Vec3Desc>>,
    /// Radiant intensity, W/sr.
    pub intensity: Option<Spanned<ColorDesc>>,
}

/// `[environment]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EnvironmentDesc {
    /// Constant radiance, or the scale of `map` (default 1 with a map).
    pub radiance: Option<Spanned<ColorDesc>>,
    /// A lat-long EXR file, relative to the scene file.
    pub map: Option<Spanned<String>>,
}

/// `albedo`: a colour, `{ checker = { a, b, scale } }` or `{ image = "file.png" }`.
#[derive(Debug)]
pub enum TextureDesc {
    Color(Color),
    Checker(CheckerDesc),
    Image(Spanned<String>),
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CheckerDesc {
    pub a: Spanned<ColorDesc>,
    pub b: Spanned<ColorDesc>,
    /// Squares per unit of the surface's `(u, v)`.
    pub scale: Spanned<Real>,
}

/// A finite number (TOML integers are accepted too).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Real(pub f32);

/// `[x, y, z]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vec3Desc(pub Vec3);

/// `[r, g, b]`, or one number for a grey.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColorDesc(pub Color);

/// `s` (uniform) or `[sx, sy, sz]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaleDesc(pub Vec3);

/// One rotation `[ax, ay, az, degrees]` or a list of them, applied to the
/// shape in the order listed.
#[derive(Clone, Debug, PartialEq)]
pub struct RotateDesc(pub Vec<[f32; 4]>);

/// Checks that a TOML number fits a finite `f32`, and that a number that is
/// not zero does not become zero (`1e-50` would, and then be reported as
/// "0" by a later check).
fn finite<E: de::Error>(v: f64) -> Result<f32, E> {
    let x = v as f32;
    if !x.is_finite() {
        Err(E::custom(format!(
            "must be a finite number (at most about 3.4e38), got {v}"
        )))
    } else if x == 0.0 && v != 0.0 {
        Err(E::custom(format!(
            "{v:e} is too close to 0 for a 32-bit float (it would become 0); use 0 or a number above about 1e-38"
        )))
    } else {
        Ok(x)
    }
}

/// Reads exactly `N` finite numbers from an array.
fn numbers<'de, A: SeqAccess<'de>, const N: usize>(mut seq: A) -> Result<[f32; N], A::Error> {
    let mut out = [0.0; N];
    for (i, slot) in out.iter_mut().enumerate() {
        match seq.next_element::<Real>()? {
            Some(Real(x)) => *slot = x,
            None => {
                return Err(de::Error::custom(format!("expected {N} numbers, got {i}")));
            }
        }
    }
    let mut extra = 0;
    while seq.next_element::<de::IgnoredAny>()?.is_some() {
        extra += 1;
    }
    if extra > 0 {
        return Err(de::Error::custom(format!(
            "expected {N} numbers, got {}",
            N + extra
        )));
    }
    Ok(out)
}

/// A visitor for "an array of N numbers", or also a single number if
/// `accepts_number`, with its own `expecting` text.
struct NumbersVisitor<const N: usize> {
    expecting: &'static str,
    accepts_number: bool,
}

enum Numbers<const N: usize> {
    One(f32),
    Many([f32; N]),
}

impl<'de, const N: usize> Visitor<'de> for NumbersVisitor<N> {
    type Value = Numbers<N>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.expecting)
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
        if self.accepts_number {
            finite(v).map(Numbers::One)
        } else {
            Err(E::invalid_type(de::Unexpected::Float(v), &self))
        }
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
        if self.accepts_number {
            Ok(Numbers::One(v as f32))
        } else {
            Err(E::invalid_type(de::Unexpected::Signed(v), &self))
        }
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
        self.visit_i64(v.min(i64::MAX as u64) as i64)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
        numbers(seq).map(Numbers::Many)
    }
}

impl<'de> Deserialize<'de> for Real {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Real;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Real, E> {
                finite(v).map(Real)
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Real, E> {
                Ok(Real(v as f32))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Real, E> {
                Ok(Real(v as f32))
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for Vec3Desc {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let visitor = NumbersVisitor::<3> {
            expecting: "an array of 3 numbers [x, y, z]",
            accepts_number: false,
        };
        match d.deserialize_any(visitor)? {
            Numbers::Many(v) => Ok(Vec3Desc(Vec3::from_array(v))),
            Numbers::One(x) => Err(de::Error::custom(format!(
                "expected an array of 3 numbers [x, y, z], got {x}"
            ))),
        }
    }
}

impl<'de> Deserialize<'de> for ColorDesc {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let visitor = NumbersVisitor::<3> {
            expecting: "a colour [r, g, b] or one number (a grey)",
            accepts_number: true,
        };
        Ok(ColorDesc(match d.deserialize_any(visitor)? {
            Numbers::One(x) => Color::splat(x),
            Numbers::Many(v) => Color::from_array(v),
        }))
    }
}

impl<'de> Deserialize<'de> for ScaleDesc {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let visitor = NumbersVisitor::<3> {
            expecting: "a number or an array [sx, sy, sz]",
            accepts_number: true,
        };
        Ok(ScaleDesc(match d.deserialize_any(visitor)? {
            Numbers::One(x) => Vec3::splat(x),
            Numbers::Many(v) => Vec3::from_array(v),
        }))
    }
}

/// What a `rotate` array turned out to be.
enum RotateItem {
    One([f32; 4]),
    List(Vec<[f32; 4]>),
}

/// The outer `rotate` array: one rotation or a list of rotations.
struct RotateVisitor;

impl<'de> Visitor<'de> for RotateVisitor {
    type Value = RotateItem;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("[ax, ay, az, degrees] or a list of them")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        // The first element decides: a number starts one rotation, an array
        // starts a list of rotations.
        let Some(first) = seq.next_element_seed(RotatePartSeed { number_ok: true })? else {
            return Ok(RotateItem::List(Vec::new()));
        };
        match first {
            RotatePart::Number(a) => {
                let mut v = [a, 0.0, 0.0, 0.0];
                let mut n = 1;
                while let Some(Real(x)) = seq.next_element::<Real>()? {
                    if n < 4 {
                        v[n] = x;
                    }
                    n += 1;
                }
                if n != 4 {
                    return Err(de::Error::custom(format!(
                        "a rotation is [ax, ay, az, degrees]: expected 4 numbers, got {n}"
                    )));
                }
                Ok(RotateItem::One(v))
            }
            RotatePart::Rotation(r) => {
                let mut list = vec![r];
                while let Some(part) = seq.next_element_seed(RotatePartSeed { number_ok: false })? {
                    if let RotatePart::Rotation(r) = part {
                        list.push(r);
                    }
                }
                Ok(RotateItem::List(list))
            }
        }
    }
}

/// One element of a `rotate` array.
enum RotatePart {
    /// A number: the array is a single rotation.
    Number(f32),
    /// A nested array: the array is a list of rotations.
    Rotation([f32; 4]),
}

/// Reads a [`RotatePart`]; numbers are refused inside a list of rotations.
struct RotatePartSeed {
    number_ok: bool,
}

impl<'de> de::DeserializeSeed<'de> for RotatePartSeed {
    type Value = RotatePart;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for RotatePartSeed {
    type Value = RotatePart;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a rotation [ax, ay, az, degrees]")
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
        if self.number_ok {
            finite(v).map(RotatePart::Number)
        } else {
            Err(E::invalid_type(de::Unexpected::Float(v), &self))
        }
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
        self.visit_f64(v as f64)
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
        self.visit_f64(v as f64)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
        numbers::<A, 4>(seq).map(RotatePart::Rotation)
    }
}

impl<'de> Deserialize<'de> for RotateDesc {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Ok(RotateDesc(match d.deserialize_any(RotateVisitor)? {
            RotateItem::One(r) => vec![r],
            RotateItem::List(list) => list,
        }))
    }
}

impl<'de> Deserialize<'de> for TextureDesc {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = TextureDesc;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(
                    "a colour [r, g, b], one number, { checker = { a = …, b = …, scale = … } } \
                     or { image = \"file.png\" }",
                )
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                finite(v).map(|x| TextureDesc::Color(Color::splat(x)))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                self.visit_f64(v as f64)
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                self.visit_f64(v as f64)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
                numbers::<A, 3>(seq).map(|v| TextureDesc::Color(Color::from_array(v)))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let Some(key) = map.next_key::<String>()? else {
                    return Err(de::Error::custom(
                        "empty texture: expected { checker = {…} } or { image = \"…\" }",
                    ));
                };
                let texture = match key.as_str() {
                    "checker" => TextureDesc::Checker(map.next_value()?),
                    "image" => TextureDesc::Image(map.next_value()?),
                    other => {
                        return Err(de::Error::custom(format!(
                            "unknown texture `{other}`, expected `checker` or `image`"
                        )));
                    }
                };
                if let Some(extra) = map.next_key::<String>()? {
                    return Err(de::Error::custom(format!(
                        "a texture has exactly one kind; remove `{extra}`"
                    )));
                }
                Ok(texture)
            }
        }
        d.deserialize_any(V)
    }
}
