//! Whether a device reproduces the CPU's terrain bit for bit (paper §3.1: the same planet on
//! every machine). The shaders follow the CPU's `f64` operations in order, but a driver need not
//! round `f64` division and square roots correctly, nor keep from fusing where the shaders go
//! to it as WGSL. A small planet adapted on both backends tells: `auto` takes a GPU only when
//! its meshes are the CPU's, so a view's bytes (and its `ETag`) never depend on the machine.

use super::{GpuAdaption, GpuError};
use crate::adapt::{Adapter, Camera};
use crate::params::Params;
use crate::planet::{build_planet, PlanetSpec};
use std::sync::Arc;

/// Faces of the canary's view: enough splits for every kind of vertex, quick on any device.
const CANARY_FACES: usize = 40_000;

/// Adapts a small planet to a close view on `gpu` and on the CPU: `Ok(true)` when the meshes
/// are equal bit for bit, `Ok(false)` when they differ, an error when the device failed.
pub fn reproduces_cpu(gpu: &Arc<GpuAdaption>) -> Result<bool, GpuError> {
    let params = Params { base_faces: 2000, ..Params::default() };
    let spec = PlanetSpec { seed: 3, params: params.clone(), map: None, precipitation: None };
    let planet = build_planet(&spec, &mut |_, _| {}).map_err(|e| GpuError::Device(format!("canary planet: {e}")))?;
    // Over a river's mouth, looking inland: sea, coast, river and continent splits.
    let mouth = planet.rivers.mouths.first().copied().unwrap_or(0);
    let dir = planet.mesh.pos(mouth).normalize();
    let r = params.radius_m;
    let eye = dir * (r + params.sea_level_m + 40_000.0);
    let target = dir * r + glam::DVec3::Z * 100_000.0;
    let cam = Camera::new(eye, target, None, 60.0, 640, 360, 2.0, 10.0, r)
        .map_err(|e| GpuError::Device(format!("canary camera: {e}")))?;
    let mut cpu = Adapter::new(planet.mesh.clone(), params.clone());
    let mut dev = Adapter::new(planet.mesh, params).with_gpu(Some(Arc::clone(gpu)));
    cpu.adapt(&cam, Some(CANARY_FACES));
    dev.adapt(&cam, Some(CANARY_FACES));
    if !dev.on_gpu() {
        return Err(GpuError::Device("the canary adaption failed on the device".into()));
    }
    Ok(cpu.mesh() == dev.mesh())
}
