//! Chapter 1 · Stereoscopy, the first half of Lecture 11: the stereo rig,
//! anaglyphs and the other ways to view a pair, crosstalk, and a light field.
//! `lesson11 stereo` runs it alone with options of its own.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, bail};
use clap::{ArgMatches, Args, FromArgMatches};
use raytracer::film::Image;
use raytracer::render::{RenderOptions, memory_needed};
use raytracer::stereo::{Anaglyph, Composite, Eye, LightField, StereoRig, crosstalk};

use crate::integrators::{IntegratorArgs, IntegratorKind};
use crate::options::{SceneArgs, check_exposure, check_memory, create_dir};
use crate::page::{Figure, Page, Section};
use crate::render_files::{render_to_files, write_png_and_exr};
use crate::tour::{Chapter, ChapterOptions, Quality, Tour};

pub const CHAPTER: Chapter = Chapter {
    name: "stereo",
    about: "1 · Stereoscopy: two eyes, anaglyphs, side-by-side, crosstalk and a light field",
    render,
    options: Some(ChapterOptions {
        augment: StereoArgs::augment_args,
        run: run_alone,
    }),
};

/// Render a stereo pair from two eyes offset along the camera's rightDir by
/// ±separation/2, and write the eye images, anaglyphs (red–cyan in colour,
/// half-colour and grey, red–blue, red–green, amber–blue, green–magenta,
/// Dubois), side-by-side / cross-eyed / over–under layouts, a crosstalk
/// preview and a light field (contact sheet and refocused images) into
/// OUT/01-stereo/, with an index.html that says what to look for.
#[derive(Args, Debug, Clone)]
struct StereoArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The algorithm that estimates each pixel.
    #[arg(long, short, value_enum, default_value = "path")]
    pub integrator: IntegratorKind,
    #[command(flatten)]
    pub integrator_args: IntegratorArgs,
    /// stereoSeparation: the full distance between the eyes in scene units; each eye
    /// moves by half of it (0.065 = a person's eyes in a scene in metres).
    #[arg(long, default_value_t = 0.065, allow_negative_numbers = true)]
    pub separation: f32,
    /// Zero-parallax distance along the view direction: what lies there appears on the
    /// screen plane (default: the camera's focus distance).
    #[arg(long, allow_negative_numbers = true)]
    pub convergence: Option<f32>,
    /// Composites to write, comma-separated: red-cyan, half-color, grey, red-blue,
    /// red-green, amber-blue, green-magenta, dubois, side-by-side, cross-eyed, over-under,
    /// left, right, or all.
    #[arg(long, value_delimiter = ',', default_value = "all")]
    pub mode: Vec<String>,
    /// Desaturation of the anaglyphs, from 0 (colours unchanged) to 1 (grey): the remedy
    /// for saturated scenes, where one eye would see holes.
    #[arg(long, default_value_t = 0.0)]
    pub desaturate: f32,
    /// Turn the eyes towards the convergence point instead of shifting their frusta
    /// (deliberately flawed: it causes vertical parallax).
    #[arg(long)]
    pub toe_in: bool,
    /// Leakage of the anaglyph filters in the crosstalk pictures (0 = perfect filters);
    /// they are written as crosstalk-EYE-leakPERCENT.png.
    #[arg(long, default_value_t = 0.3)]
    pub leakage: f32,
    /// Light field: views per side of the N×N grid (0 = no light field).
    #[arg(long, default_value_t = 5)]
    pub lf_views: u32,
    /// Light field: side of the square aperture the views cover, in scene units.
    #[arg(long, default_value_t = 0.4)]
    pub lf_aperture: f32,
    /// Light field: the views are rendered this many times smaller than the eyes
    /// (1: the eyes' size, which the slides show the pair of views at).
    #[arg(long, default_value_t = 1)]
    pub lf_downscale: u32,
    /// Light field: samples per pixel of each view (default: a sixteenth of --spp, at least 1;
    /// a refocused picture averages all the views, so it has views × this many).
    #[arg(long)]
    pub lf_spp: Option<u32>,
    /// Light field: depths to refocus at, comma-separated (default: half, once and
    /// three times the convergence distance).
    #[arg(long, value_delimiter = ',')]
    pub refocus: Vec<f32>,
    /// Exposure in stops for the PNGs (+1 doubles the brightness); EXRs are never changed.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub exposure: f32,
}

impl Default for StereoArgs {
    fn default() -> Self {
        StereoArgs {
            scene: SceneArgs {
                out: PathBuf::from("out/lesson11"),
                ..SceneArgs::default()
            },
            integrator: IntegratorKind::Path,
            integrator_args: IntegratorArgs::default(),
            separation: 0.065,
            convergence: None,
            mode: vec!["all".into()],
            desaturate: 0.0,
            toe_in: false,
            leakage: 0.3,
            lf_views: 5,
            lf_aperture: 0.4,
            lf_downscale: 1,
            lf_spp: None,
            refocus: Vec::new(),
            exposure: 0.0,
        }
    }
}

/// The folder of this chapter inside `--out`.
const CHAPTER_DIR: &str = "01-stereo";

/// Chapter 1: stereoscopy (see `lesson11 stereo --help` for every option).
fn render(tour: &Tour) -> Result<Section> {
    let mut args = StereoArgs::default();
    args.scene.out = tour.out.clone();
    args.scene.threads = tour.threads;
    match tour.quality {
        Quality::Tiny => {
            args.scene.width = Some(32);
            args.scene.height = Some(24);
            args.scene.spp = Some(2);
            args.lf_views = 2;
            args.lf_spp = Some(1);
        }
        Quality::Quick => args.scene.spp = Some(32),
        Quality::Full => args.scene.spp = Some(256),
    }
    let o = &tour.overrides;
    args.scene.width = o.width.or(args.scene.width);
    args.scene.height = o.height.or(args.scene.height);
    args.scene.spp = o.spp.or(args.scene.spp);
    args.scene.seed = o.seed;
    render_section(&args, &tour.out)
}

/// `lesson11 stereo`: the chapter alone, with its page in `OUT/01-stereo/index.html`.
fn run_alone(matches: &ArgMatches) -> Result<()> {
    let args = StereoArgs::from_arg_matches(matches)?;
    let dir = args.scene.out.join(CHAPTER_DIR);
    let section = render_section(&args, &dir)?;
    let mut page = Page::new(lang::pick(
        "Lecture 11: stereoscopy",
        "Лекция 11: стереоскопия",
    ));
    page.sections.push(section);
    let index = page.write(&dir, "index.html")?;
    let index = index.display();
    crate::console::say!(
        "{}",
        lang::pick(
            format!("open {index} to see the pictures"),
            format!("отворете {index}, за да видите картините"),
        )
    );
    Ok(())
}

/// The composites `--mode` names, in order, without repeats.
pub fn parse_modes(names: &[String]) -> Result<Vec<Composite>> {
    let mut modes: Vec<Composite> = Vec::new();
    for name in names {
        let found = if name.trim().eq_ignore_ascii_case("all") {
            Composite::all()
        } else {
            vec![name.parse::<Composite>().map_err(anyhow::Error::msg)?]
        };
        for m in found {
            if !modes.contains(&m) {
                modes.push(m);
            }
        }
    }
    Ok(modes)
}

/// Checks the options that clap cannot.
fn check(args: &StereoArgs) -> Result<()> {
    if !(0.0..=1.0).contains(&args.desaturate) {
        bail!(
            "{} {}",
            lang::pick(
                "--desaturate must lie in [0, 1] (0 = colours unchanged, 1 = grey), got",
                "--desaturate трябва да е в [0, 1] (0 = цветовете без промяна, 1 = сиво), а е"
            ),
            args.desaturate
        );
    }
    if !(0.0..=1.0).contains(&args.leakage) {
        bail!(
            "{} {}",
            lang::pick(
                "--leakage must lie in [0, 1], got",
                "--leakage трябва да е в [0, 1], а е"
            ),
            args.leakage
        );
    }
    if args.lf_views > 0 && !(args.lf_aperture.is_finite() && args.lf_aperture >= 0.0) {
        bail!(
            "{} {}",
            lang::pick(
                "--lf-aperture must be a distance ≥ 0, got",
                "--lf-aperture трябва да е разстояние ≥ 0, а е"
            ),
            args.lf_aperture
        );
    }
    if args.lf_downscale == 0 {
        bail!(lang::pick(
            "--lf-downscale must be at least 1",
            "--lf-downscale трябва да е поне 1"
        ));
    }
    if args.lf_spp == Some(0) {
        bail!(lang::pick(
            "--lf-spp must be at least 1",
            "--lf-spp трябва да е поне 1"
        ));
    }
    if let Some(d) = args.refocus.iter().find(|d| !(d.is_finite() && **d > 0.0)) {
        bail!(
            "{} {d}",
            lang::pick(
                "--refocus depths must be positive, got",
                "дълбочините на --refocus трябва да са положителни, а една е"
            )
        );
    }
    check_exposure(args.exposure)
}

/// The light field's views, before they are rendered: `n × n` images of
/// `w × h` pixels in memory at once (12 bytes a pixel) beside one render's
/// film.
fn check_light_field_memory(args: &StereoArgs, w: u32, h: u32) -> Result<()> {
    let n = args.lf_views as u64;
    let views = n
        .checked_mul(n)
        .and_then(|v| v.checked_mul(w as u64 * h as u64 * 12));
    let bytes = views.and_then(|v| v.checked_add(memory_needed(w, h)?));
    check_memory(
        &lang::pick(
            format!("a light field of {n}×{n} views of {w}×{h}"),
            format!("светлинно поле от {n}×{n} изгледа по {w}×{h}"),
        ),
        bytes,
        lang::pick(
            "--lf-views or a larger --lf-downscale",
            "--lf-views или по-голям --lf-downscale",
        ),
        args.scene.force,
    )?;
    if n > 0xffff {
        bail!(
            "{} {n}",
            lang::pick(
                "--lf-views must be at most 65535 (the views are counted in 32 bits), got",
                "--lf-views трябва да е най-много 65535 (изгледите се броят в 32 бита), а е"
            )
        );
    }
    Ok(())
}

/// Writes `dir/stem.png` and `dir/stem.exr`; returns them as a figure
/// linked relative to `page_root`.
fn save(
    image: &Image,
    dir: &Path,
    page_root: &Path,
    stem: &str,
    exposure: f32,
    caption: String,
) -> Result<Figure> {
    let (png, exr) = write_png_and_exr(image, dir, stem, exposure)?;
    let shown = png.display();
    crate::console::say!(
        "{}",
        lang::pick(
            format!("  wrote {shown} and .exr"),
            format!("  записах {shown} и .exr"),
        )
    );
    Ok(Figure::image(page_root, &png, &exr, caption))
}

/// What to look for in each composite, in the run's language.
fn caption(mode: Composite) -> String {
    use raytracer::stereo::Layout;
    let (en, bg) = match mode {
        Composite::Anaglyph(Anaglyph::RedCyan) => (
            "Red–cyan anaglyph in colour (red filter on the left eye). Saturated red or cyan \
             objects reach one eye only and shimmer: try --desaturate 0.5.",
            "Червено-циан анаглиф в пълен цвят (червеният филтър е пред лявото око). Наситено \
             червените или циан обекти стигат само до едното око и трептят: опитайте \
             --desaturate 0.5.",
        ),
        Composite::Anaglyph(Anaglyph::HalfColor) => (
            "Red–cyan half-colour: the left eye gets the luminance, so red objects no longer \
             vanish for one eye; the right keeps some colour.",
            "Червено-циан, полуцветен: лявото око получава яркостта, така че червените обекти \
             вече не изчезват за едното око; дясното запазва част от цвета.",
        ),
        Composite::Anaglyph(Anaglyph::Grey) => (
            "Red–cyan grey: no colour, but both eyes see the same brightness everywhere \
             (easiest to fuse).",
            "Червено-циан, сив: без цвят, но двете очи виждат една и съща яркост навсякъде \
             (най-лесно се сливат).",
        ),
        Composite::Anaglyph(Anaglyph::Dubois) => (
            "Dubois least-squares red–cyan: the best colour and the least ghosting of the \
             red–cyan anaglyphs.",
            "Червено-циан анаглиф на Dubois (метод на най-малките квадрати): най-добрият цвят и \
             най-малко ghosting сред червено-циан анаглифите.",
        ),
        Composite::Anaglyph(a) => {
            let glasses = match a {
                Anaglyph::RedBlue => "червено (ляво) – синьо (дясно)",
                Anaglyph::RedGreen => "червено (ляво) – зелено (дясно)",
                Anaglyph::AmberBlue => "жълто (ляво) – синьо (дясно)",
                Anaglyph::GreenMagenta => "зелено (ляво) – магента (дясно)",
                _ => "червено (ляво) – циан (дясно)",
            };
            return lang::pick(
                format!("Anaglyph for {} glasses.", a.glasses()),
                format!("Анаглиф за очила {glasses}."),
            );
        }
        Composite::Layout(Layout::SideBySide) => (
            "Side by side for parallel viewing: left image on the left; look through the screen \
             as at something far away (keep the pictures small).",
            "Една до друга за успореден метод: картинката за лявото око е отляво; гледайте през \
             екрана като към нещо далечно (дръжте картинките малки).",
        ),
        Composite::Layout(Layout::CrossEyed) => (
            "Cross-eyed: the right eye's image on the left; cross your eyes until the two middle \
             pictures merge into a third one in depth.",
            "Кръстосан метод: картинката за дясното око е отляво; кръстосайте поглед, докато \
             двете средни картинки се слеят в трета, обемна.",
        ),
        Composite::Layout(Layout::OverUnder) => (
            "Over–under: left eye on top (for viewers and projectors).",
            "Една над друга: лявото око е отгоре (за специални зрители и прожектори).",
        ),
        Composite::Eye(e) => {
            return lang::pick(
                format!("The {} eye's image.", e.name()),
                format!("Картината на {} око.", eye_bg(e)),
            );
        }
    };
    lang::pick(en, bg).into()
}

/// "лявото" or "дясното": the eye in a Bulgarian sentence.
fn eye_bg(eye: Eye) -> &'static str {
    match eye {
        Eye::Left => "лявото",
        Eye::Right => "дясното",
    }
}

/// Renders everything into `args.scene.out/01-stereo/` and returns the page
/// section, its figures linked relative to `page_root`.
fn render_section(args: &StereoArgs, page_root: &Path) -> Result<Section> {
    check(args)?;
    let modes = parse_modes(&args.mode)?;
    let rig = StereoRig {
        separation: args.separation,
        convergence: args.convergence,
        toe_in: args.toe_in,
    };
    rig.validate()?;
    let (scene, options) = args.scene.load("stereo")?;
    let integrator =
        args.integrator
            .build(&args.integrator_args, &scene, &options, args.scene.force)?;
    if args.lf_views > 0 {
        let (w, h) = light_field_size(args, &scene);
        check_light_field_memory(args, w, h)?;
    }
    let dir = args.scene.out.join(CHAPTER_DIR);
    create_dir(&dir)?;
    let convergence = rig.convergence_distance(&scene.camera.params);
    let (eyes, separation, name, spp) = (
        match (rig.toe_in, lang::current()) {
            (true, lang::Lang::En) => "toed-in",
            (false, lang::Lang::En) => "parallel, off-axis",
            (true, lang::Lang::Bg) => "завъртени навътре (toe-in)",
            (false, lang::Lang::Bg) => "успоредни, с изместени пирамиди (off-axis)",
        },
        rig.separation,
        integrator.name(),
        options.spp,
    );
    crate::console::say!(
        "{}",
        lang::pick(
            format!(
                "01 · stereo: {eyes} eyes {separation} apart, zero parallax at {convergence:.3} ({name}, {spp} spp)"
            ),
            format!(
                "01 · стерео: очи {eyes} на {separation} една от друга, нулев паралакс на {convergence:.3} ({name}, {spp} spp)"
            ),
        )
    );

    let mut section = Section::new(
        lang::pick("01 · Stereoscopy", "01 · Стереоскопия"),
        &section_text(args, convergence),
    );

    // The two eyes, same seed: identical random sequences.
    let mut eye_scene = scene.clone();
    let mut eyes = Vec::new();
    for (camera, eye) in rig.eyes(&scene.camera).into_iter().zip(Eye::BOTH) {
        eye_scene.camera = camera;
        let opts = RenderOptions {
            label: match eye {
                Eye::Left => lang::pick(
                    format!("{} left eye", scene.name),
                    format!("{} ляво око", scene.name),
                ),
                Eye::Right => lang::pick(
                    format!("{} right eye", scene.name),
                    format!("{} дясно око", scene.name),
                ),
            },
            ..options.clone()
        };
        let picture = render_to_files(
            &eye_scene,
            integrator.as_ref(),
            &opts,
            &dir,
            eye.name(),
            args.exposure,
        )?;
        let image = Image::read_exr(&picture.exr)
            .with_context(|| format!("cannot read back {}", picture.exr.display()))?;
        section.figures.push(Figure::new(
            page_root,
            &picture,
            &lang::pick(
                format!("The {} eye.", eye.name()),
                match eye {
                    Eye::Left => "Лявото око.".into(),
                    Eye::Right => "Дясното око.".into(),
                },
            ),
        ));
        eyes.push(image);
    }
    let (left, right) = (&eyes[0], &eyes[1]);

    for mode in modes.iter().filter(|m| !matches!(m, Composite::Eye(_))) {
        let image = mode.compose(left, right, args.desaturate);
        let mut text = caption(*mode);
        if matches!(mode, Composite::Anaglyph(_)) && args.desaturate > 0.0 {
            let d = args.desaturate;
            text.push_str(&lang::pick(
                format!(" Desaturated by {d}."),
                format!(" Обезцветен с {d}."),
            ));
        }
        section.figures.push(save(
            &image,
            &dir,
            page_root,
            mode.name(),
            args.exposure,
            text,
        )?);
    }

    if modes.contains(&Composite::Anaglyph(Anaglyph::RedCyan)) {
        eye_views(args, left, right, &dir, page_root, &mut section)?;
    }
    if modes.contains(&Composite::Anaglyph(Anaglyph::Dubois)) {
        separation_sweep(
            args,
            &scene,
            integrator.as_ref(),
            &options,
            &dir,
            page_root,
            &mut section,
        )?;
    }

    if args.lf_views > 0 {
        light_field(
            args,
            &scene,
            integrator.as_ref(),
            &options,
            convergence,
            &dir,
            page_root,
            &mut section,
        )?;
    }
    Ok(section)
}

/// The size of each light-field view: the eyes' size over `--lf-downscale`.
fn light_field_size(args: &StereoArgs, scene: &raytracer::scene::Scene) -> (u32, u32) {
    (
        (scene.camera.width / args.lf_downscale).max(1),
        (scene.camera.height / args.lf_downscale).max(1),
    )
}

/// What each eye sees of the colour red–cyan anaglyph through its filter:
/// perfect filters at the run's `--desaturate`, perfect filters after
/// desaturating by 0.5 (the lecture's remedy), and filters leaking
/// `--leakage` of the other colours (ghosting). Each view is the brightness
/// the eye gets, as grey ([`crosstalk::eye_view`]).
fn eye_views(
    args: &StereoArgs,
    left: &Image,
    right: &Image,
    dir: &Path,
    page_root: &Path,
    section: &mut Section,
) -> Result<()> {
    let glasses = Anaglyph::RedCyan;
    let filter = |eye: Eye| match eye {
        Eye::Left => lang::pick("red", "червен"),
        Eye::Right => lang::pick("cyan", "циан"),
    };
    let anaglyph = glasses.compose(left, right, args.desaturate);
    let perfect = crosstalk::eye_views(&anaglyph, glasses, 0.0);
    let desaturated = crosstalk::eye_views(&glasses.compose(left, right, 0.5), glasses, 0.0);
    let leaky = crosstalk::eye_views(&anaglyph, glasses, args.leakage);
    let at = if args.desaturate > 0.0 {
        let d = args.desaturate;
        lang::pick(
            format!(", the anaglyph desaturated by {d}"),
            format!(", анаглифът обезцветен с {d}"),
        )
    } else {
        String::new()
    };
    let pct = (100.0 * args.leakage).round() as u32;
    for (k, eye) in Eye::BOTH.into_iter().enumerate() {
        let (name, bg) = (eye.name(), eye_bg(eye));
        let red_ball = match eye {
            Eye::Left => lang::pick(
                "the near red ball is bright",
                "близката червена топка е светла",
            ),
            Eye::Right => lang::pick(
                "the near red ball turns dark, since little of its light is green or blue: the \
                 two eyes see it differently",
                "близката червена топка потъмнява, защото в светлината ѝ има малко зелено и \
                 синьо: двете очи я виждат различно",
            ),
        };
        let f = filter(eye);
        section.figures.push(save(
            &perfect[k],
            dir,
            page_root,
            &format!("filtered-{name}"),
            args.exposure,
            lang::pick(
                format!(
                    "What the {name} eye sees of the red–cyan anaglyph through a perfect {f} \
                     filter (leakage 0{at}), as brightness: {red_ball}."
                ),
                format!(
                    "Какво вижда {bg} око от червено-циан анаглифа през съвършен {f} филтър \
                     (пропускане 0{at}), като яркост: {red_ball}."
                ),
            ),
        )?);
        let back = match eye {
            Eye::Left => lang::pick(
                "the red ball a little dimmer",
                "червената топка е малко по-тъмна",
            ),
            Eye::Right => lang::pick(
                "the red ball brighter, closer to what the left eye sees",
                "червената топка е по-светла, по-близо до това, което вижда лявото око",
            ),
        };
        section.figures.push(save(
            &desaturated[k],
            dir,
            page_root,
            &format!("filtered-{name}-desat50"),
            args.exposure,
            lang::pick(
                format!(
                    "The same for the {name} eye after desaturating both frames by 0.5 before \
                     mixing: {back}."
                ),
                format!(
                    "Същото за {bg} око след обезцветяване на двата кадъра с 0.5 преди \
                     смесването: {back}."
                ),
            ),
        )?);
        section.figures.push(save(
            &leaky[k],
            dir,
            page_root,
            &format!("crosstalk-{name}-leak{pct}"),
            args.exposure,
            lang::pick(
                format!(
                    "What the {name} eye sees through filters leaking {pct} % of the other \
                     colours{at}: the faint doubled edges are ghosting, the other eye's frame \
                     showing through."
                ),
                format!(
                    "Какво вижда {bg} око през филтри, които пропускат {pct} % от чуждите \
                     цветове{at}: бледите двойни ръбове са ghosting – кадърът на другото око \
                     прозира."
                ),
            ),
        )?);
    }
    Ok(())
}

/// The stereo separations of the sweep: almost flat, a person's eyes, a giant's.
const SWEEP: [f32; 3] = [0.02, 0.065, 0.3];

/// Dubois anaglyphs of the scene at the separations of [`SWEEP`], all with
/// the same convergence distance, at 0.64 of the eyes' size and about a
/// third of their samples (what the sweep shows is depth, not detail).
#[allow(clippy::too_many_arguments)]
fn separation_sweep(
    args: &StereoArgs,
    scene: &raytracer::scene::Scene,
    integrator: &dyn raytracer::integrator::Integrator,
    options: &RenderOptions,
    dir: &Path,
    page_root: &Path,
    section: &mut Section,
) -> Result<()> {
    // 0.64 of the eyes' size (256×192 from 400×300: the width the slide
    // shows them at, with no blowing up) and as many pixel samples as half
    // the size at half the samples: 0.25 / 0.64² of the eyes' samples.
    let mut small = scene.clone();
    let (w, h) = (
        (scene.camera.width * 16 / 25).max(1),
        (scene.camera.height * 16 / 25).max(1),
    );
    small.set_resolution(w, h);
    let spp = (options.spp * 10 / 32).max(1);
    let start = Instant::now();
    for separation in SWEEP {
        let rig = StereoRig {
            separation,
            convergence: args.convergence,
            toe_in: args.toe_in,
        };
        rig.validate()?;
        let mut eye_scene = small.clone();
        let mut eyes = Vec::new();
        for (camera, eye) in rig.eyes(&small.camera).into_iter().zip(Eye::BOTH) {
            eye_scene.camera = camera;
            let opts = RenderOptions {
                spp,
                progress: false,
                label: lang::pick(
                    format!("{} {} eye, separation {separation}", scene.name, eye.name()),
                    format!("{} {} око, разделение {separation}", scene.name, eye_bg(eye)),
                ),
                ..options.clone()
            };
            eyes.push(raytracer::render::render(&eye_scene, integrator, &opts).film.image());
        }
        if raytracer::render::interrupted() {
            bail!(lang::pick(
                "interrupted by Ctrl-C while rendering the separation sweep",
                "прекъснато с Ctrl-C по време на рендерирането на разделенията"
            ));
        }
        let look = if separation < 0.05 {
            lang::pick("almost flat", "почти плоско")
        } else if separation < 0.1 {
            lang::pick("a person's eyes, in metres", "очите на човек, в метри")
        } else {
            lang::pick(
                "a giant's eyes: exaggerated depth, the scene looks like a model",
                "очите на великан: преувеличена дълбочина, сцената изглежда като макет",
            )
        };
        section.figures.push(save(
            &Anaglyph::Dubois.compose(&eyes[0], &eyes[1], args.desaturate),
            dir,
            page_root,
            &format!("separation-{separation:.3}"),
            args.exposure,
            lang::pick(
                format!(
                    "stereoSeparation {separation}: {look}. Dubois anaglyph, zero parallax at the \
                     same distance for every separation ({w}×{h}, {spp} spp per eye)."
                ),
                format!(
                    "stereoSeparation {separation}: {look}. Анаглиф на Dubois, нулев паралакс на \
                     едно и също разстояние при всяко разделение ({w}×{h}, {spp} spp на око)."
                ),
            ),
        )?);
    }
    let (pairs, seconds) = (SWEEP.len(), start.elapsed().as_secs_f64());
    crate::console::say!(
        "{}",
        lang::pick(
            format!("  separation sweep: {pairs} pairs of {w}×{h} at {spp} spp in {seconds:.1} s"),
            format!("  разделенията: {pairs} двойки по {w}×{h} с {spp} spp за {seconds:.1} s"),
        )
    );
    Ok(())
}

/// Renders the light field and writes its contact sheet, refocused images
/// and an anaglyph of a pair from the grid.
#[allow(clippy::too_many_arguments)]
fn light_field(
    args: &StereoArgs,
    scene: &raytracer::scene::Scene,
    integrator: &dyn raytracer::integrator::Integrator,
    options: &RenderOptions,
    convergence: f32,
    dir: &Path,
    page_root: &Path,
    section: &mut Section,
) -> Result<()> {
    let n = args.lf_views;
    let mut lf_scene = scene.clone();
    let (w, h) = light_field_size(args, scene);
    lf_scene.set_resolution(w, h);
    let spp = args.lf_spp.unwrap_or((options.spp / 16).max(1));
    let lf_options = RenderOptions {
        spp,
        label: lang::pick(
            format!("{} light field", scene.name),
            format!("{} светлинно поле", scene.name),
        ),
        ..options.clone()
    };
    let start = Instant::now();
    let lf = LightField::render(&lf_scene, integrator, &lf_options, n, args.lf_aperture);
    if raytracer::render::interrupted() {
        bail!(lang::pick(
            "interrupted while rendering the light field; its pictures were not written",
            "прекъснато по време на рендерирането на светлинното поле; картините му не са записани"
        ));
    }
    let seconds = start.elapsed().as_secs_f64();
    crate::console::say!(
        "{}",
        lang::pick(
            format!("  light field: {n}×{n} views of {w}×{h} at {spp} spp in {seconds:.1} s"),
            format!("  светлинно поле: {n}×{n} изгледа по {w}×{h} с {spp} spp за {seconds:.1} s"),
        )
    );
    section.figures.push(save(
        &lf.contact_sheet(2),
        dir,
        page_root,
        "lightfield-contact",
        args.exposure,
        {
            let a = args.lf_aperture;
            lang::pick(
                format!(
                    "The light field: {n}×{n} pinhole views across a {a} × {a} aperture, as seen \
                     from the front (top row = highest eye). Near objects shift most between the \
                     views."
                ),
                format!(
                    "Light field: {n}×{n} pinhole изгледа през отвор {a} × {a}, гледани отпред \
                     (горният ред = най-високото око). Близките обекти се изместват най-много \
                     между изгледите."
                ),
            )
        },
    )?);
    let mut depths = if args.refocus.is_empty() {
        vec![0.5 * convergence, convergence, 3.0 * convergence]
    } else {
        args.refocus.clone()
    };
    // A depth asked twice is one picture.
    let mut seen = Vec::new();
    depths.retain(|d| {
        let new = !seen.contains(d);
        seen.push(*d);
        new
    });
    let digits = refocus_digits(&depths);
    for depth in depths {
        section.figures.push(save(
            &lf.refocus(depth),
            dir,
            page_root,
            &format!("refocus-{depth:.digits$}"),
            args.exposure,
            lang::pick(
                format!(
                    "Refocused at {depth:.digits$} by shift-and-add: what lies at that depth is \
                     sharp, the rest is blurred as by a lens as wide as the aperture."
                ),
                format!(
                    "Префокусирано на {depth:.digits$} чрез изместване и усредняване на изгледите: \
                     каквото е на тази дълбочина, е рязко, останалото е размито като зад леща, \
                     широка колкото отвора."
                ),
            ),
        )?);
    }
    if n >= 2 {
        let row = n / 2;
        let [l, r] = lf.stereo_pair(row, 0, n - 1, Some(convergence));
        section.figures.push(save(
            &Anaglyph::Dubois.compose(&l, &r, args.desaturate),
            dir,
            page_root,
            "lightfield-pair-dubois",
            args.exposure,
            {
                let a = args.lf_aperture;
                lang::pick(
                    format!(
                        "A stereo pair taken out of the light field (the outermost views of the \
                         middle row, {a} apart), converged at {convergence:.2}: Dubois red–cyan \
                         anaglyph."
                    ),
                    format!(
                        "Стерео двойка, извадена от light field-а (крайните изгледи на средния \
                         ред, на {a} един от друг), с конвергенция на {convergence:.2}: \
                         червено-циан анаглиф на Dubois."
                    ),
                )
            },
        )?);
    }
    Ok(())
}

/// The explanation at the top of the section, in the run's language.
fn section_text(args: &StereoArgs, convergence: f32) -> String {
    let method = match (args.toe_in, lang::current()) {
        (true, lang::Lang::En) => {
            "These eyes are toed in: each turns towards the convergence point. Their image planes \
             are no longer parallel, so objects near the corners sit at different heights in the \
             two images (vertical parallax): compare the left and right images near the corners, \
             and notice the strain when fusing them. Run without --toe-in for the correct rig."
        }
        (false, lang::Lang::En) => {
            "The eyes look in parallel and each image window is shifted sideways (an off-axis \
             frustum), so that the two frusta meet at the convergence distance: whatever lies \
             there appears on the screen plane with zero parallax, nearer things come out of the \
             screen and farther ones go into it, and nothing has vertical parallax. Run with \
             --toe-in to see the flawed alternative."
        }
        (true, lang::Lang::Bg) => {
            "Тези очи са завъртени навътре (toe-in): всяко се обръща към точката на конвергенция. \
             Равнините на картините им вече не са успоредни, затова обектите близо до ъглите са \
             на различна височина в двете картини (вертикален паралакс): сравнете лявата и \
             дясната картина край ъглите и усетете напрежението, докато ги сливате. Пуснете без \
             --toe-in за правилната постановка."
        }
        (false, lang::Lang::Bg) => {
            "Очите гледат успоредно, а прозорецът на всяка картина е изместен встрани (изместена, \
             off-axis пирамида на видимост), така че двете пирамиди се срещат на разстоянието на \
             конвергенция: каквото лежи там, се появява в равнината на екрана с нулев паралакс, \
             по-близкото излиза пред екрана, по-далечното влиза зад него, а вертикален паралакс \
             няма. Пуснете с --toe-in, за да видите сбъркания вариант."
        }
    };
    let sep = args.separation;
    lang::pick(
        format!(
            "Two eyes offset along the camera's rightDir by ±stereoSeparation/2 (separation {sep}; \
             some of the course's C++ renderers offset by ±separation instead, which doubles the \
             effect). {method} Zero parallax at {convergence:.2}. A larger separation makes the \
             scene look smaller and deeper, too large looks wrong, too small looks flat: tune it \
             for each scene. Both eyes use the same random numbers, so their noise matches and \
             does not shimmer. The anaglyphs are mixed in linear RGB, before sRGB encoding, \
             because filters and screens act on light, which adds linearly. Look at the near red \
             ball: it has little green or blue, so through the cyan filter the right eye sees it \
             dark and the left eye bright (the filtered views show what each eye gets, as \
             brightness): the eyes see different pictures and struggle to fuse them. Desaturating \
             both frames a little before mixing (here by 0.5) brings it back at the cost of \
             colour; half-colour and grey anaglyphs do the same, and Dubois' matrices keep the \
             most colour. Filters that leak let part of the other frame through: the doubled \
             edges of ghosting. The separation sweep shows stereoSeparation 0.02, 0.065 and 0.3 \
             with the same convergence distance: almost flat, a person's eyes, a giant's. The \
             light field is a grid of pinhole views: averaging them shifted for one depth \
             refocuses the picture after rendering, and any two views of a row form a stereo \
             pair."
        ),
        format!(
            "Две очи, изместени по посоката rightDir на камерата с ±stereoSeparation/2 \
             (разделение {sep}; някои от C++ рендерерите на курса изместват всяко око с цялото \
             ±stereoSeparation, което удвоява ефекта). {method} Нулев паралакс на {convergence:.2}. По-голямото разделение \
             прави сцената да изглежда по-малка и по-дълбока; прекалено голямото изглежда \
             сбъркано, прекалено малкото – плоско: настройва се за всяка сцена. Двете очи ползват \
             едни и същи случайни числа, затова шумът им съвпада и не трепти. Анаглифите се \
             смесват в линейното RGB пространство, преди sRGB кодирането, защото филтрите и \
             екраните действат върху светлината, а светлината се събира линейно. Вижте близката \
             червена топка: в нея има малко зелено и синьо, затова през циан филтъра дясното око \
             я вижда тъмна, а лявото – светла (филтрираните изгледи показват какво получава всяко \
             око, като яркост): очите виждат различни картини и трудно ги сливат. Малко \
             обезцветяване на двата кадъра преди смесването (тук с 0.5) я връща, с цената на \
             цветовете; полуцветните и сивите анаглифи правят същото, а матриците на Dubois пазят \
             най-много цвят. Филтри, които пропускат, оставят част от другия кадър да прозира: \
             двойните ръбове на ghosting. Редицата от разделения показва stereoSeparation 0.02, \
             0.065 и 0.3 при едно и също разстояние на конвергенция: почти плоско, очите на \
             човек, очите на великан. Light field-ът е решетка от pinhole изгледи: усреднени с \
             изместване за една дълбочина, те префокусират картината след рендерирането, а всеки \
             два изгледа от един ред са стерео двойка."
        ),
    )
}

/// The fewest decimals (at least 2) that give every refocus depth a name of
/// its own: `--refocus 2.001,2.004` wrote both to `refocus-2.00.*`, the
/// second over the first.
pub fn refocus_digits(depths: &[f32]) -> usize {
    (2..=9)
        .find(|&d| {
            let mut names: Vec<String> = depths.iter().map(|x| format!("{x:.d$}")).collect();
            names.sort();
            names.dedup();
            names.len() == depths.len()
        })
        .unwrap_or(9)
}
