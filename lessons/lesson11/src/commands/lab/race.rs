//! The Race tab: the lecture's equal-time comparison happening in front of
//! the class. Two or three integrators render the same scene at once, each
//! on one thread of its own (the same share of the processors: with fewer
//! cores than integrators the operating system shares them out), and each
//! snapshot's RMSE against an independent reference is plotted against
//! time on log–log axes, where a Monte Carlo estimator's error falls as a
//! line of slope −1/2 and the better estimator is the lower line.
//!
//! The references are the ones the tour measures against
//! (`crate::reference`): Mitsuba 3's Cornell box (256×256, max depth 65) and
//! the stored door and caustic scenes (128×96, max depths 5 and 8), at any
//! size that divides theirs; every racer renders at the reference's max
//! depth.

use super::job::{JobSpec, Racers};
use super::query::Query;
use super::settings::{RENDER_PARAMS, SceneFolder, render_setup};
use crate::integrators::IntegratorPlan;
use crate::reference::{
    MITSUBA_MAX_DEPTH, Reference, caustic_settings, door_settings, mitsuba_cornell,
};

/// The race's own parameters.
pub const RACE_PARAMS: &[&str] = &["racers", "seconds"];

/// The longest race, in seconds.
pub const LONGEST: f64 = 300.0;

/// The scenes with a stored reference, and the max depth it was made with.
fn reference(scene: &str, width: u32, height: u32) -> Result<(Reference, u32), String> {
    let (stored, depth) = match scene {
        "cornell" => (mitsuba_cornell(), MITSUBA_MAX_DEPTH),
        "door" => (door_settings().load(), door_settings().max_depth),
        "caustic" => (caustic_settings().load(), caustic_settings().max_depth),
        _ => {
            return Err(lang::pick(
                format!(
                    "the race measures against a stored reference: choose cornell, door or caustic, not {scene:?}"
                ),
                format!(
                    "надпреварата мери спрямо записан еталон: изберете cornell, door или caustic, а не {scene:?}"
                ),
            ));
        }
    };
    let stored = stored.map_err(|e| format!("{e:#}"))?;
    let (w, h) = (stored.mean.width, stored.mean.height);
    let at = stored.at_size(width, height).ok_or_else(|| {
        lang::pick(
            format!(
                "the reference of {scene} is {w}×{h}: choose a size that divides it (e.g. {}×{})",
                w / 2,
                h / 2
            ),
            format!(
                "еталонът на {scene} е {w}×{h}: изберете размер, който го дели (напр. {}×{})",
                w / 2,
                h / 2
            ),
        )
    })?;
    Ok((at, depth))
}

/// The race the query describes: `racers=path,light,bdpt` (2 or 3
/// integrators of pixel samples), `seconds`, and the render options of
/// `lesson11 render` for all of them (the max depth is the reference's).
pub fn race_job(q: &Query, folder: &SceneFolder) -> Result<JobSpec, String> {
    let names: Vec<&str> = q
        .get("racers")
        .unwrap_or("path,bdpt")
        .split(',')
        .map(str::trim)
        .filter(|n| !n.is_empty())
        .collect();
    if !(2..=3).contains(&names.len()) {
        return Err(lang::pick(
            format!("a race takes 2 or 3 integrators, got {}", names.len()),
            format!(
                "надпреварата е между 2 или 3 интегратора, а са {}",
                names.len()
            ),
        ));
    }
    let seconds = q.in_range("seconds", 20.0, 1.0..=LONGEST as f32)? as f64;
    let scene_name = q.get("scene").unwrap_or("cornell").to_string();
    let mut racers = Vec::new();
    let mut first = None;
    for name in &names {
        // Each racer's options as `lesson11 render` reads them; the max
        // depth and the target come from the race.
        let mut words: Vec<String> = q
            .iter()
            .filter(|(k, _)| {
                RENDER_PARAMS.contains(k) && !["integrator", "max-depth", "spp"].contains(k)
            })
            .map(|(k, v)| format!("{k}={v}"))
            .collect();
        words.push(format!("integrator={name}"));
        words.push("spp=65536".into());
        let probe = Query::parse(&words.join("&"), RENDER_PARAMS)?;
        let setup = render_setup(&probe, folder, "cornell", "path")?;
        let (w, h) = (setup.scene.camera.width, setup.scene.camera.height);
        let (reference, depth) = reference(&scene_name, w, h)?;
        words.push(format!("max-depth={depth}"));
        let q = Query::parse(&words.join("&"), RENDER_PARAMS)?;
        let setup = render_setup(&q, folder, "cornell", "path")?;
        let IntegratorPlan::Ready(integrator) = setup.plan else {
            return Err(format!(
                "{name} builds maps or runs chains before its first sample: the race takes \
                 integrators of pixel samples (path, path-brdf, path-nee, light, bdpt, direct, naive)"
            ));
        };
        racers.push(integrator);
        first.get_or_insert((setup.scene, setup.options, reference));
    }
    let (scene, options, reference) = first.expect("two racers at least");
    let floor = reference.noise_floor();
    Ok(JobSpec {
        kind: "race",
        command: lang::pick(
            format!(
                "an equal-time race of {} for {seconds} s, one thread each",
                names.join(", ")
            ),
            format!(
                "надпревара за еднакво време между {} за {seconds} s, по една нишка",
                names.join(", ")
            ),
        ),
        eyes: vec![scene; racers.len()],
        build_for: None,
        plan: IntegratorPlan::Ready(Box::new(raytracer::integrator::PathTracer::default())),
        options,
        wavefront: None,
        student: None,
        race: Some(Racers {
            integrators: racers,
            seconds,
            reference: std::sync::Arc::new(reference.mean),
            floor,
        }),
    })
}
