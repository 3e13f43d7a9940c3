//! Chapter 3 · BRDFs: the hemisphere at a point (the lecture's figure of
//! n, ω_i, ω_o, θ_i and dω_i), lobes in the plane of incidence, directional albedo
//! (energy conservation) of normalized and unnormalized Phong, reciprocity,
//! and a gallery of the lecture's BRDFs, path traced.

use anyhow::Result;
use lang::Lang;
use raytracer::brdf::{Brdf, Lambert, Phong, Texture, TransportMode};
use raytracer::integrator::PathTracer;
use raytracer::math::{Color, Vec2, Vec3A};
use raytracer::sampling::Sampler;

use crate::page::{Figure, Section, Table};
use crate::plots::{
    Chart, Hemisphere, HemisphereWords, LANGS, Scale, Series, hemisphere_svg, polar_svg,
};
use crate::tour::{Chapter, ChapterOutput, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "brdf",
    "3 · BRDFs: lobes, directional albedo of normalized and unnormalized Phong, reciprocity, a gallery",
    render,
);

/// Chapter 3: BRDFs.
fn render(tour: &Tour) -> Result<Section> {
    // `--scene` replaces the chapters' Cornell box; this chapter has none.
    // Said, not silently ignored (`brdf -s furnace` rendered the gallery).
    if let Some(other) = &tour.overrides.scene {
        eprintln!(
            "{}",
            lang::pick(
                format!(
                    "note: --scene {other} does not apply to the BRDF chapter: it shows the BRDF gallery \
                     (brdf-gallery) and plots the lobes"
                ),
                format!(
                    "бележка: --scene {other} не важи за главата за BRDF: тя показва галерията от BRDF-и \
                     (brdf-gallery) и рисува лобовете"
                ),
            )
        );
    }
    let mut s = tour.chapter(
        "03-brdf",
        lang::pick("3 · BRDFs", "3 · BRDF-и"),
        lang::pick(
        "A BRDF f_r(x, ω_i, ω_o) says how much of the light arriving at x from direction ω_i is \
         reflected towards ω_o. Both directions point away from x: ω_o towards the viewer, ω_i \
         towards where the light comes from (the lecture's ω_i points the other way, into the \
         surface, hence its factor (−ω_i·n) = cos θ_i); the first figure shows them on the \
         hemisphere above x. The lecture calls f_r \"how likely\" light from ω_i is reflected \
         towards ω_o: a good intuition, but exactly it is a density over \
         directions, in sr⁻¹, the reflected radiance per unit of light arriving from a small cone \
         dω_i, and it can exceed 1 (Phong with n = 100 reaches 11.09 in the reciprocity table \
         below, and (n+2)/2π ≈ 16.2 at its peak). What may not exceed 1 is its integral, the \
         directional albedo ∫ f_r cos θ dω: that is energy conservation. The plots show lobes in \
         the plane of incidence, the directional albedo of normalized and unnormalized Phong, and \
         reciprocity. The normalization S(n) = (n+2)/2π makes the albedo exactly 1 at normal \
         incidence only: at grazing angles part of the lobe falls below the surface and the albedo \
         drops below 1. The albedo table is a Monte Carlo estimate, so it prints each value's \
         standard error beside it and judges it against 1 with that error. The render shows \
         Lambert, normalized Phong with n = 1, 10, 100 and 1000, a perfect mirror and glass, path \
         traced: as n grows the highlight narrows and brightens.",
        "BRDF-ът f_r(x, ω_i, ω_o) казва каква част от светлината, дошла в x от посока ω_i, се \
         отразява към ω_o. И двете посоки сочат навън от x: ω_o – към наблюдателя, ω_i – натам, \
         откъдето идва светлината (ω_i в лекцията сочи обратно, към повърхността, оттам и \
         множителят ѝ (−ω_i·n) = cos θ_i); първата фигура ги показва върху полусферата над x. \
         Лекцията описва f_r като „вероятността“ светлина от ω_i да се отрази към ω_o: добра \
         интуиция, но точно казано това е плътност по посоките, в sr⁻¹ – отразената radiance \
         на единица светлина, дошла от малкия конус dω_i – и може да надхвърля 1 (Phong с n = \
         100 стига 11.09 в таблицата на симетричността по-долу и (n+2)/2π ≈ 16.2 във върха си). \
         Не бива да надхвърля 1 интегралът ѝ, албедото по посоки ∫ f_r cos θ dω: това е \
         запазването на енергията. Графиките показват лобове в равнината на падане, албедото \
         по посоки на нормирания и ненормирания Phong, и симетричността. Нормировката S(n) = \
         (n+2)/2π прави албедото точно 1 само при перпендикулярно падане: под полегати ъгли \
         част от лоба попада под повърхността и албедото пада под 1. Таблицата на албедото е \
         Monte Carlo оценка, затова до всяка стойност стои стандартната ѝ грешка и с нея \
         стойността се сравнява с 1. Рендерът показва Lambert, нормиран Phong с n = 1, 10, 100 \
         и 1000, съвършено огледало и стъкло, с path tracing: с растящо n отблясъкът се \
         стеснява и става по-ярък.",
        ),
    )?;
    hemisphere(&mut s, tour)?;
    plots_and_tables(&mut s, tour)?;
    let (scene, options) = tour.scene("brdf-gallery", 32)?;
    let pt = PathTracer::default();
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &options,
        "brdf-gallery",
        lang::pick(
            "The BRDF gallery, path traced: Lambert, normalized Phong with n = 1, 10, 100, 1000, \
             a mirror and glass.",
            "Галерията от BRDF-и, path tracing: Lambert, нормиран Phong с n = 1, 10, 100, 1000, \
             огледало и стъкло.",
        ),
    )?;
    Ok(s.section)
}

/// The lecture's figure of the hemisphere at x, one SVG per language of the
/// slides (`hemisphere-en.svg`, `hemisphere-bg.svg`); the page shows the one
/// of its language.
fn hemisphere(c: &mut ChapterOutput, tour: &Tour) -> Result<()> {
    let h = Hemisphere::default();
    for lang in LANGS {
        let words = HemisphereWords::for_lang(lang).expect("the figure's languages have words");
        raytracer::film::output::write_file(
            c.dir.join(format!("hemisphere-{lang}.svg")),
            hemisphere_svg(&h, &words),
        )?;
    }
    let (i, o) = (h.theta_i_deg, h.theta_o_deg);
    c.section.figures.push(Figure::plot(
        &tour.out,
        &c.dir.join(format!("hemisphere-{}.svg", lang::current())),
        &lang::pick(
            format!(
                "The hemisphere Ω above a point x, drawn from the directions themselves: both \
                 unit vectors leave x, ω_i towards the light ({i}° from the normal n) and ω_o \
                 towards the viewer ({o}°); θ_i is the angle between ω_i and n, cos θ_i = ω_i·n; \
                 dω_i is a small cone of directions around ω_i. Dashed: the way the light \
                 travels, −ω_i, the lecture's ω_i. With Bulgarian labels: hemisphere-bg.svg."
            ),
            format!(
                "Полусферата Ω над точка x, начертана по самите посоки: и двата единични вектора \
                 излизат от x, ω_i – към светлината ({i}° от нормалата n), ω_o – към \
                 наблюдателя ({o}°); θ_i е ъгълът между ω_i и n, cos θ_i = ω_i·n; dω_i е малък \
                 конус от посоки около ω_i. С пунктир: посоката, в която пътува светлината, \
                 −ω_i – ω_i в лекцията. С английски надписи: hemisphere-en.svg."
            ),
        ),
    ));
    Ok(())
}

fn phong(n: f32) -> Brdf {
    Brdf::Phong(Phong {
        albedo: Color::ONE,
        exponent: n,
    })
}

fn lambert() -> Brdf {
    Brdf::Lambert(Lambert {
        albedo: Texture::Constant(Color::ONE),
    })
}

/// A direction in the plane of incidence (x–z), θ from the normal.
fn dir(theta: f64) -> Vec3A {
    Vec3A::new(theta.sin() as f32, 0.0, theta.cos() as f32)
}

/// Directional albedo `∫ f_r cos θ_i dω_i` for light leaving towards `wo`,
/// estimated with the BRDF's own sampling: the mean of `f cos / pdf` over
/// `samples` directions, and the standard error of that mean.
fn directional_albedo(brdf: &Brdf, wo: Vec3A, samples: u32) -> (f64, f64) {
    let (mut sum, mut squares) = (0.0f64, 0.0f64);
    for i in 0..samples {
        let mut sampler = Sampler::new(3, i as u64, 0);
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        if let Some(bs) = brdf.sample(wo, Vec2::ZERO, u_lobe, u, TransportMode::Radiance) {
            let x = (bs.f.x * bs.wi.z.abs() / bs.pdf_w) as f64;
            sum += x;
            squares += x * x;
        }
    }
    let n = samples as f64;
    let mean = sum / n;
    let variance = ((squares / n - mean * mean) * n / (n - 1.0).max(1.0)).max(0.0);
    (mean, (variance / n).sqrt())
}

/// How many standard errors an albedo may lie above 1 before it counts as
/// creating energy: a one-sided 4σ test, false alarm about 3·10⁻⁵ per row.
const SIGMAS: f64 = 4.0;

/// What an estimated albedo `a ± se` says about energy conservation, in `l`.
fn verdict(l: Lang, a: f64, se: f64) -> String {
    if se == 0.0 {
        return if (a - 1.0).abs() < 1e-6 {
            l.pick(
                "exactly 1 in every sample (zero variance): conserves energy, none lost",
                "точно 1 при всяка проба (нулева дисперсия): запазва енергията, без загуба",
            )
            .into()
        } else if a < 1.0 {
            l.pick(
                format!("{a:.4} in every sample: conserves energy"),
                format!("{a:.4} при всяка проба: запазва енергията"),
            )
        } else {
            l.pick(
                format!("{a:.4} in every sample: creates energy"),
                format!("{a:.4} при всяка проба: създава енергия"),
            )
        };
    }
    let z = (a - 1.0) / se;
    let lost = 100.0 * (1.0 - a);
    if z > SIGMAS {
        l.pick(
            format!("above 1 by {z:.0} standard errors: creates energy"),
            format!("над 1 с {z:.0} стандартни грешки: създава енергия"),
        )
    } else if z >= -SIGMAS {
        l.pick(
            format!("1 within its noise (z = {z:+.1}): conserves energy, none lost"),
            format!("1 в рамките на шума си (z = {z:+.1}): запазва енергията, без загуба"),
        )
    } else {
        l.pick(
            format!(
                "below 1 by more than {SIGMAS} standard errors: conserves energy, loses {lost:.0} %"
            ),
            format!(
                "под 1 с повече от {SIGMAS} стандартни грешки: запазва енергията, губи {lost:.0} %"
            ),
        )
    }
}

/// A positive number with two significant digits (0.0027, 0.0000068), so
/// that a small standard error is not printed as 0.
fn two_digits(x: f64) -> String {
    if x <= 0.0 {
        return "0".into();
    }
    let decimals = (1 - x.log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The smallest f_r drawn on the log axis of the lobes' true heights.
const LOBE_FLOOR: f64 = 0.01;

/// The plots and tables: lobes, directional albedo and reciprocity.
fn plots_and_tables(c: &mut ChapterOutput, tour: &Tour) -> Result<()> {
    let samples = if tour.quality == Quality::Tiny {
        256
    } else {
        16384
    };

    // Lobes for light arriving 30° from the normal: f_r over outgoing
    // directions in the plane of incidence, each scaled to its peak (the
    // shapes), and again at their true heights on a log axis.
    let incoming = 30f64.to_radians();
    let wi = dir(-incoming);
    let mut lobes = Vec::new();
    let mut heights = Vec::new();
    for (label, brdf) in [
        ("Lambert", lambert()),
        ("Phong n=1", phong(1.0)),
        ("Phong n=10", phong(10.0)),
        ("Phong n=100", phong(100.0)),
    ] {
        let points: Vec<(f64, f64)> = (0..=180)
            .map(|k| {
                let theta = (k as f64 - 90.0).to_radians();
                (theta, brdf.eval(dir(theta), wi, Vec2::ZERO).x as f64)
            })
            .collect();
        let peak = points.iter().map(|p| p.1).fold(1e-12, f64::max);
        heights.push(Series {
            label: label.into(),
            points: points
                .iter()
                .filter(|p| p.1 >= LOBE_FLOOR)
                .map(|&(t, r)| (t.to_degrees(), r))
                .collect(),
        });
        lobes.push(Series {
            label: label.into(),
            points: points.into_iter().map(|(t, r)| (t, r / peak)).collect(),
        });
    }
    lobes.push(Series {
        label: "mirror (a delta)".into(),
        points: vec![(0.0, 0.0), (incoming, 1.0)],
    });
    for lang in LANGS {
        let bg = lang == "bg";
        let mut lobes_here = lobes.clone();
        if bg {
            if let Some(mirror) = lobes_here.last_mut() {
                mirror.label = "огледало (делта)".into();
            }
        }
        raytracer::film::output::write_file(
            c.dir.join(format!("lobes-{lang}.svg")),
            polar_svg(
                if bg {
                    "Лобове на BRDF, светлина от 30°, всеки до върха си"
                } else {
                    "BRDF lobes, light from 30°, each scaled to its peak"
                },
                &lobes_here,
                30.0,
                if bg { "падаща" } else { "incoming" },
            ),
        )?;
        Chart {
            title: if bg {
                "f_r при светлина от 30°: истинските височини"
            } else {
                "f_r for light from 30°: the true heights"
            }
            .into(),
            x_label: if bg {
                "θ_o в равнината на падане (градуси)"
            } else {
                "θ_o in the plane of incidence (degrees)"
            }
            .into(),
            y_label: "f_r (1/sr)".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Log,
            series: heights.clone(),
        }
        .write(&c.dir.join(format!("lobe-heights-{lang}.svg")))?;
    }
    let here = lang::current();
    c.section.figures.push(Figure::plot(
        &tour.out,
        &c.dir.join(format!("lobes-{here}.svg")),
        lang::pick(
            "Lobes in the plane of incidence: Phong narrows around the mirror direction as n \
             grows; Lambert is a half circle. Each is scaled to its own peak (the shapes); the \
             next plot shows their true heights.",
            "Лобове в равнината на падане: с растящо n лобът на Phong се стеснява около \
             огледалната посока; лобът на Lambert е полуокръжност. Всеки е мащабиран спрямо \
             върха си (формите); следващата графика показва истинските им височини.",
        ),
    ));
    c.section.figures.push(Figure::plot(
        &tour.out,
        &c.dir.join(format!("lobe-heights-{here}.svg")),
        &lang::pick(
            format!(
                "The same lobes at their true heights, f_r on a log axis (values below \
                 {LOBE_FLOOR} left out): a narrower normalized lobe is taller, so that its albedo \
                 stays at most 1 — Lambert flat, the same in every direction, Phong n = 100 about \
                 16 at the mirror direction."
            ),
            format!(
                "Същите лобове в истинските им височини, f_r по логаритмична ос (стойностите под \
                 {LOBE_FLOOR} са изпуснати): по-тесният нормиран лоб е по-висок, за да остане \
                 албедото му най-много 1 – Lambert е плосък, еднакъв във всяка посока, Phong с \
                 n = 100 около 16 в огледалната посока."
            ),
        ),
    ));

    // Directional albedo against the angle of the outgoing direction.
    let mut albedo = Chart {
        title: "Directional albedo ∫ f_r cos θ dω".into(),
        x_label: "θ_o (degrees)".into(),
        y_label: "albedo".into(),
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: Vec::new(),
    };
    let mut table = Table::in_both(
        &lang::pick(
            format!(
                "Directional albedo at normal incidence, estimated with {samples} BRDF samples \
                 each: ≤ 1 conserves energy, judged with the standard error (above 1 by more than \
                 {SIGMAS} standard errors creates energy)"
            ),
            format!(
                "Албедо по посоки при перпендикулярно падане, оценено с по {samples} проби по \
                 BRDF-а: ≤ 1 запазва енергията, преценено със стандартната грешка (над 1 с \
                 повече от {SIGMAS} стандартни грешки създава енергия)"
            ),
        ),
        &[
            ("BRDF", "BRDF"),
            ("albedo (estimate)", "албедо (оценка)"),
            ("standard error", "стандартна грешка"),
            ("exact", "точно"),
            ("verdict", "извод"),
        ],
    );
    let mut row = |label: &dyn Fn(Lang) -> String, (a, se): (f64, f64), exact: f64| {
        table.push(|l| {
            vec![
                label(l),
                format!("{a:.4}"),
                two_digits(se),
                format!("{exact:.4}"),
                verdict(l, a, se),
            ]
        });
    };
    row(
        &|_| "Lambert".into(),
        directional_albedo(&lambert(), Vec3A::Z, samples),
        1.0,
    );
    for n in [1.0f32, 10.0, 100.0] {
        let brdf = phong(n);
        // Without the factor (n+2)/2π the BRDF is the normalized one times 2π/(n+2).
        let unnormalize = 2.0 * std::f64::consts::PI / (n as f64 + 2.0);
        let at = |deg: f64| directional_albedo(&brdf, dir(deg.to_radians()), samples);
        let (a, se) = at(0.0);
        row(&|_| format!("Phong n = {n}, S(n) = (n+2)/2π"), (a, se), 1.0);
        row(
            &|l| {
                l.pick(
                    format!("Phong n = {n}, unnormalized (S = 1)"),
                    format!("Phong n = {n}, ненормиран (S = 1)"),
                )
            },
            (a * unnormalize, se * unnormalize),
            unnormalize,
        );
        let angles: Vec<f64> = (0..=17).map(|k| k as f64 * 5.0).collect();
        let values: Vec<f64> = angles.iter().map(|&a| at(a).0).collect();
        albedo.series.push(Series {
            label: format!("n={n}"),
            points: angles.iter().copied().zip(values.iter().copied()).collect(),
        });
        albedo.series.push(Series {
            label: format!("n={n} unnorm."),
            points: angles
                .iter()
                .copied()
                .zip(values.iter().map(|v| v * unnormalize))
                .collect(),
        });
    }
    albedo.write(&c.dir.join("albedo-en.svg"))?;
    albedo.title = "Албедо по посоки ∫ f_r cos θ dω".into();
    albedo.x_label = "θ_o (градуси)".into();
    albedo.y_label = "албедо".into();
    for series in &mut albedo.series {
        series.label = series.label.replace("unnorm.", "ненорм.");
    }
    albedo.write(&c.dir.join("albedo-bg.svg"))?;
    let path = c.dir.join(format!("albedo-{here}.svg"));
    c.section.figures.push(Figure::plot(
        &tour.out,
        &path,
        lang::pick(
            "Directional albedo against the angle of ω_o: normalized Phong is 1 at normal \
             incidence (exactly; the estimate within its standard error) and less at grazing \
             angles, where part of the lobe falls below the surface; unnormalized Phong with n = 1 \
             reflects more than it receives, with n = 100 far less.",
            "Албедо по посоки спрямо ъгъла на ω_o: нормираният Phong е 1 при перпендикулярно \
             падане (точно; оценката – в рамките на стандартната си грешка) и по-малко под \
             полегати ъгли, където част от лоба попада под повърхността; ненормираният Phong с \
             n = 1 отразява повече, отколкото получава, а с n = 100 – много по-малко.",
        ),
    ));
    table.write_csv(&c.dir.join("albedo.csv"))?;
    c.section.tables.push(table);

    // Reciprocity: f(ω_i → ω_o) = f(ω_o → ω_i).
    // Symbols and numbers only: the same in both languages.
    let mut table = Table::new(
        lang::pick(
            "Reciprocity: f_r(a → b) and f_r(b → a)",
            "Симетричност: f_r(a → b) и f_r(b → a)",
        ),
        &["BRDF", "a (θ°)", "b (θ°)", "f(a→b)", "f(b→a)"],
    );
    for (label, brdf) in [
        ("Lambert", lambert()),
        ("Phong n=10", phong(10.0)),
        ("Phong n=100", phong(100.0)),
    ] {
        for (a, b) in [(-20.0f64, 25.0f64), (-60.0, 50.0), (-5.0, 10.0)] {
            let (da, db) = (dir(a.to_radians()), dir(b.to_radians()));
            let (ab, ba) = (brdf.eval(db, da, Vec2::ZERO).x, brdf.eval(da, db, Vec2::ZERO).x);
            table.push(|_| {
                vec![
                    label.into(),
                    format!("{a}"),
                    format!("{b}"),
                    format!("{ab:.5}"),
                    format!("{ba:.5}"),
                ]
            });
        }
    }
    table.write_csv(&c.dir.join("reciprocity.csv"))?;
    c.section.tables.push(table);
    Ok(())
}
