//! The one line a biased integrator's build prints (photon mapping, instant
//! radiosity, irradiance caching: lecture part 9), in the program's language.
//! `raytracer` keeps its English `summary()` and knows no language; this
//! file says the same facts from the built integrator in Bulgarian.

use raytracer::integrator::irradiance_cache::Strata;
use raytracer::integrator::photon::Photon;
use raytracer::integrator::vpl::Vpl;
use raytracer::integrator::{InstantRadiosity, IrradianceCache, PhotonMapping};

/// `bytes` in MiB.
fn mib(bytes: usize) -> f64 {
    bytes as f64 / (1 << 20) as f64
}

/// ", INTERRUPTED" if `interrupted`.
fn interrupted_bg(interrupted: bool) -> &'static str {
    if interrupted {
        ", ПРЕКЪСНАТО"
    } else {
        ""
    }
}

/// "photon maps: N light paths, C caustic + G global photons × B bytes = M MiB (…)".
pub fn photon_maps(pm: &PhotonMapping) -> String {
    if lang::current() == lang::Lang::En {
        return pm.summary();
    }
    let s = &pm.stats;
    format!(
        "фотонни карти: {} светлинни пътя, {} каустични + {} глобални фотона × {} байта = \
         {:.1} MiB (проследени за {:.2} s, построени за {:.2} s){}",
        s.paths,
        s.caustic_photons,
        s.global_photons,
        std::mem::size_of::<Photon>(),
        mib(s.bytes),
        s.tracing.as_secs_f64(),
        s.building.as_secs_f64(),
        interrupted_bg(s.interrupted)
    )
}

/// "instant radiosity: N light paths, V VPLs × B bytes = M MiB (…)".
pub fn vpls(ir: &InstantRadiosity) -> String {
    if lang::current() == lang::Lang::En {
        return ir.summary();
    }
    format!(
        "instant radiosity: {} светлинни пътя, {} VPL × {} байта = {:.2} MiB \
         (проследени за {:.2} s){}",
        ir.paths,
        ir.vpls().len(),
        std::mem::size_of::<Vpl>(),
        mib(ir.bytes()),
        ir.tracing.as_secs_f64(),
        interrupted_bg(ir.interrupted)
    )
}

/// "irradiance cache: a = …, R records × B bytes = M MiB (…)".
pub fn irradiance_cache(ic: &IrradianceCache) -> String {
    if lang::current() == lang::Lang::En {
        return ic.summary();
    }
    let rays = if ic.settings.gradients {
        let s = Strata::for_rays(ic.settings.rays);
        format!(
            "по {} лъча в {} × {} страти, с градиенти",
            s.rays(),
            s.m,
            s.n
        )
    } else {
        format!("по {} лъча", ic.settings.rays)
    };
    format!(
        "irradiance кеш: a = {}, {} записа × {} байта = {:.2} MiB ({rays}, построен за {:.2} s){}",
        ic.settings.error,
        ic.records().len(),
        ic.record_bytes(),
        mib(ic.bytes()),
        ic.building.as_secs_f64(),
        interrupted_bg(ic.interrupted)
    )
}
