//! The Stereo tab: both eyes of `raytracer::stereo::StereoRig` rendered
//! progressively side by side in time (two threads, the same seed, so their
//! noise is correlated as in `lesson11 stereo`), and composed on every
//! request: each anaglyph, side-by-side, cross-eyed, over–under or one eye,
//! with desaturation. Changing the separation or the convergence starts a
//! new render; changing the composite or the desaturation only composes
//! the pictures already rendered again.

use raytracer::film::Image;
use raytracer::stereo::{Composite, StereoRig};

use super::job::JobSpec;
use super::query::Query;
use super::settings::{SceneFolder, one_line, render_setup};
use crate::integrators::IntegratorPlan;

/// The parameters of the rig.
pub const RIG_PARAMS: &[&str] = &["separation", "convergence", "toe-in"];

/// The parameters of the composite.
pub const COMPOSITE_PARAMS: &[&str] = &["mode", "desaturate"];

/// Both eyes of the scene the query describes (the `stereo` scene and path
/// tracing unless it says otherwise).
pub fn stereo_job(q: &Query, folder: &SceneFolder) -> Result<JobSpec, String> {
    let setup = render_setup(q, folder, "stereo", "path")?;
    // `lesson11 stereo` renders pixel samples only.
    setup.plan.check_pixel_samples().map_err(|e| one_line(&e))?;
    let convergence = match q.get("convergence") {
        None | Some("") => None,
        Some(_) => Some(q.in_range("convergence", 1.0, 1e-3..=1e4)?),
    };
    let rig = StereoRig {
        separation: q.in_range("separation", 0.065, 0.0..=100.0)?,
        convergence,
        toe_in: q.flag("toe-in")?,
    };
    rig.validate().map_err(|e| e.to_string())?;
    let eyes = rig
        .eyes(&setup.scene.camera)
        .map(|camera| {
            let mut scene = setup.scene.clone();
            scene.camera = camera;
            scene
        })
        .to_vec();
    let mut command = format!(
        "cargo run --release -p lesson11 -- stereo {} --separation {}",
        setup.options_line, rig.separation
    );
    if let Some(c) = rig.convergence {
        command += &format!(" --convergence {c}");
    }
    if rig.toe_in {
        command += " --toe-in";
    }
    command += " --lf-views 0";
    // A build (the irradiance cache) is made for the rig's centre, as
    // `lesson11 stereo` makes it.
    let build_for = matches!(setup.plan, IntegratorPlan::Biased(_)).then_some(setup.scene);
    Ok(JobSpec {
        kind: "stereo",
        command,
        eyes,
        build_for,
        plan: setup.plan,
        options: setup.options,
        student: None,
        race: None,
        wavefront: setup.wavefront,
    })
}

/// The composite the query names (`mode`, `desaturate`) of the two eyes.
pub fn compose(q: &Query, left: &Image, right: &Image) -> Result<Image, String> {
    let mode: Composite = q.get("mode").unwrap_or("red-cyan").parse()?;
    let desaturate = q.in_range("desaturate", 0.0, 0.0..=1.0)?;
    Ok(mode.compose(left, right, desaturate))
}

/// Every composite's name, for the page's list.
pub fn composite_names() -> Vec<&'static str> {
    Composite::all().into_iter().map(Composite::name).collect()
}
