// The refinement criterion (paper §5.1, eq. 6): the twin of `View::wants_split` in
// `src/adapt/camera.rs`, operation for operation and in the same order, in f64 on the mesh's own
// planet-centred positions. Appended to the stages that decide split wishes (the state update,
// and the collapses for the edges they restore); each declares `vertices` and `view` (the
// layout of `View` in `layout.wgsl`).

fn position(v: u32) -> vec3<f64> {
    let p = vertices[v].pos;
    return vec3<f64>(p[0], p[1], p[2]);
}

fn wants_split(lod_len: f64, centre: vec3<f64>, radius: f64, sea: bool) -> bool {
    if lod_len < f64(2.0) * view.min_len {
        return false;
    }
    // Back-face culling: the whole ball lies behind the horizon plane.
    if dot3(centre, triple(view.eye_dir)) + radius < view.horizon {
        return false;
    }
    let rel = centre - triple(view.eye);
    let len = sqrt(dot3(rel, rel));
    var d = max(len - radius, f64(1e-3));
    var c = view.c_land;
    if sea {
        c = view.c_water;
    }
    // Eq. 6 only lengthens d: an edge short enough already is refused without it.
    if lod_len <= c * d {
        return false;
    }
    var outside = f64(0.0);
    for (var i = 0u; i < 5u; i++) {
        outside = max(outside, (-dot3(triple(view.planes[i]), rel) - radius) * view.per_unit[i]);
    }
    let q = outside / max(len + radius, f64(1e-3));
    d = d * (f64(1.0) + view.c_lod * q * q); // eq. 6
    return lod_len > c * d;
}

