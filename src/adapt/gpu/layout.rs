//! The GPU layouts of adaption in one home: the parameter blocks the stages read as uniforms,
//! twins of the structs of `shaders/adapt/layout.wgsl` (with the mesh buffers `Vertex`, `Edge`,
//! `Face` of `crate::mesh` and `GuideFace` of `crate::mesh::guide`, whose WGSL twins live there
//! too). The test below reads `layout.wgsl` with naga and checks every struct's size and every
//! member's offset against the Rust one, so the two sides cannot drift apart.
//!
//! What fills a block is the stage's business (`impl GpuView` in `state.rs`, `impl SplitParams`
//! in `split.rs`, ...); here are only the layouts.

use bytemuck::{Pod, Zeroable};

/// The view as `view.wgsl` reads it (`struct View`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct GpuView {
    pub(crate) eye: [f64; 3],
    pub(crate) planes: [[f64; 3]; 5],
    pub(crate) per_unit: [f64; 5],
    pub(crate) eye_dir: [f64; 3],
    pub(crate) horizon: f64,
    pub(crate) c_land: f64,
    pub(crate) c_water: f64,
    pub(crate) min_len: f64,
    pub(crate) c_lod: f64,
    /// Edges to decide.
    pub(crate) edges: u32,
    /// Invocations per row of the dispatch grid (edge = x + y * row).
    pub(crate) row: u32,
}

/// The terrain parameters and batch shape as `split.wgsl` reads them (`struct SplitParams`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct SplitParams {
    pub(crate) radius: f64,
    pub(crate) sea_level: f64,
    pub(crate) riverbed_edge_height: f64,
    pub(crate) max_river_depth: f64,
    pub(crate) min_river_length: f64,
    pub(crate) max_river_altitude: f64,
    pub(crate) max_mountain_altitude: f64,
    pub(crate) riverbed_slope: f64,
    pub(crate) near_river_slope: f64,
    pub(crate) ground_slope: f64,
    pub(crate) river_slope: f64,
    pub(crate) quality_scale: f64,
    pub(crate) min_quality: f64,
    pub(crate) one: f64,
    pub(crate) half: f64,
    pub(crate) quarter: f64,
    pub(crate) three_quarters: f64,
    pub(crate) sea_roughness: f64,
    pub(crate) roughness: f64,
    pub(crate) roughness_length: f64,
    pub(crate) sea_roughness_length: f64,
    pub(crate) tangent_scale: f64,
    pub(crate) tangent_offset: f64,
    pub(crate) guide_min_edge: f64,
    pub(crate) floor_slope: f64,
    pub(crate) floor_length: f64,
    pub(crate) relief: f64,
    pub(crate) altitude_gain: f64,
    pub(crate) hybrid: f64,
    pub(crate) relief_length: f64,
    pub(crate) smooth_length: f64,
    pub(crate) threshold: f64,
    pub(crate) map_relief: f64,
    pub(crate) ridge: f64,
    pub(crate) floor_fade: f64,
    pub(crate) altitude_length: f64,
    pub(crate) sea_detail: f64,
    pub(crate) vertices: u32,
    pub(crate) edges: u32,
    pub(crate) faces: u32,
    pub(crate) count: u32,
    pub(crate) row: u32,
    pub(crate) guide_faces: u32,
    pub(crate) guide_side: u32,
    pub(crate) _pad: u32,
}

/// A vertex-wise dispatch of the collapse stages as the shaders read it (`struct Sweep`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct Sweep {
    pub(crate) vertices: u32,
    /// Invocations per row of the dispatch grid (vertex = x + y * row).
    pub(crate) row: u32,
    /// 1: candidates only among the vertices the last collapses marked to look at.
    pub(crate) among: u32,
    pub(crate) _pad: u32,
}

/// The shape of a block prefix sum as `scan.wgsl` reads it (`struct Grid`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct ScanGrid {
    /// Items to scan.
    pub(crate) items: u32,
    /// Invocations per row of an item-wise dispatch of `WORKGROUP` (item = x + y * row).
    pub(crate) row: u32,
    /// Blocks of `BLOCK` items, and workgroups per row of the block-wise dispatch.
    pub(crate) blocks: u32,
    pub(crate) block_row: u32,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::guide::GuideFace;
    use crate::mesh::{Edge, Face, Vertex};
    use std::mem::{offset_of, size_of};

    /// A struct's name, size and `(member, offset)` list.
    type Layout<S> = (S, usize, Vec<(S, usize)>);

    /// Every struct of `layout.wgsl`, as naga lays it out.
    fn wgsl_structs() -> Vec<Layout<String>> {
        let module = naga::front::wgsl::parse_str(super::super::shaders::LAYOUT).expect("layout.wgsl parses");
        module
            .types
            .iter()
            .filter_map(|(_, ty)| match &ty.inner {
                naga::TypeInner::Struct { members, span } => Some((
                    ty.name.clone().unwrap_or_default(),
                    *span as usize,
                    members.iter().map(|m| (m.name.clone().unwrap_or_default(), m.offset as usize)).collect(),
                )),
                _ => None,
            })
            .collect()
    }

    /// Each WGSL struct has the size of its Rust twin and each member the offset of the Rust
    /// field it reads (a packed word: the offset of its first field), and no struct is left
    /// unchecked.
    #[test]
    fn every_wgsl_layout_matches_its_rust_twin() {
        let twins: Vec<Layout<&str>> = vec![
            (
                "Vertex",
                size_of::<Vertex>(),
                vec![
                    ("pos", offset_of!(Vertex, pos)),
                    ("ground", offset_of!(Vertex, ground)),
                    ("water", offset_of!(Vertex, water)),
                    ("edge", offset_of!(Vertex, edge)),
                    ("parent_lod", offset_of!(Vertex, parent_lod)),
                    ("seed", offset_of!(Vertex, seed)),
                    ("bits", offset_of!(Vertex, tangent)),
                ],
            ),
            (
                "Edge",
                size_of::<Edge>(),
                vec![
                    ("v", offset_of!(Edge, v)),
                    ("f", offset_of!(Edge, f)),
                    ("lod", offset_of!(Edge, lod)),
                    ("bits", offset_of!(Edge, level)),
                ],
            ),
            ("Face", size_of::<Face>(), vec![("e", offset_of!(Face, e))]),
            (
                "Sweep",
                size_of::<Sweep>(),
                vec![
                    ("vertices", offset_of!(Sweep, vertices)),
                    ("row", offset_of!(Sweep, row)),
                    ("among", offset_of!(Sweep, among)),
                    ("_pad", offset_of!(Sweep, _pad)),
                ],
            ),
            (
                "View",
                size_of::<GpuView>(),
                vec![
                    ("eye", offset_of!(GpuView, eye)),
                    ("planes", offset_of!(GpuView, planes)),
                    ("per_unit", offset_of!(GpuView, per_unit)),
                    ("eye_dir", offset_of!(GpuView, eye_dir)),
                    ("horizon", offset_of!(GpuView, horizon)),
                    ("c_land", offset_of!(GpuView, c_land)),
                    ("c_water", offset_of!(GpuView, c_water)),
                    ("min_len", offset_of!(GpuView, min_len)),
                    ("c_lod", offset_of!(GpuView, c_lod)),
                    ("edges", offset_of!(GpuView, edges)),
                    ("row", offset_of!(GpuView, row)),
                ],
            ),
            (
                "SplitParams",
                size_of::<SplitParams>(),
                vec![
                    ("radius", offset_of!(SplitParams, radius)),
                    ("sea_level", offset_of!(SplitParams, sea_level)),
                    ("riverbed_edge_height", offset_of!(SplitParams, riverbed_edge_height)),
                    ("max_river_depth", offset_of!(SplitParams, max_river_depth)),
                    ("min_river_length", offset_of!(SplitParams, min_river_length)),
                    ("max_river_altitude", offset_of!(SplitParams, max_river_altitude)),
                    ("max_mountain_altitude", offset_of!(SplitParams, max_mountain_altitude)),
                    ("riverbed_slope", offset_of!(SplitParams, riverbed_slope)),
                    ("near_river_slope", offset_of!(SplitParams, near_river_slope)),
                    ("ground_slope", offset_of!(SplitParams, ground_slope)),
                    ("river_slope", offset_of!(SplitParams, river_slope)),
                    ("quality_scale", offset_of!(SplitParams, quality_scale)),
                    ("min_quality", offset_of!(SplitParams, min_quality)),
                    ("one", offset_of!(SplitParams, one)),
                    ("half", offset_of!(SplitParams, half)),
                    ("quarter", offset_of!(SplitParams, quarter)),
                    ("three_quarters", offset_of!(SplitParams, three_quarters)),
                    ("sea_roughness", offset_of!(SplitParams, sea_roughness)),
                    ("roughness", offset_of!(SplitParams, roughness)),
                    ("roughness_length", offset_of!(SplitParams, roughness_length)),
                    ("sea_roughness_length", offset_of!(SplitParams, sea_roughness_length)),
                    ("tangent_scale", offset_of!(SplitParams, tangent_scale)),
                    ("tangent_offset", offset_of!(SplitParams, tangent_offset)),
                    ("guide_min_edge", offset_of!(SplitParams, guide_min_edge)),
                    ("floor_slope", offset_of!(SplitParams, floor_slope)),
                    ("floor_length", offset_of!(SplitParams, floor_length)),
                    ("relief", offset_of!(SplitParams, relief)),
                    ("altitude_gain", offset_of!(SplitParams, altitude_gain)),
                    ("hybrid", offset_of!(SplitParams, hybrid)),
                    ("relief_length", offset_of!(SplitParams, relief_length)),
                    ("smooth_length", offset_of!(SplitParams, smooth_length)),
                    ("threshold", offset_of!(SplitParams, threshold)),
                    ("map_relief", offset_of!(SplitParams, map_relief)),
                    ("ridge", offset_of!(SplitParams, ridge)),
                    ("floor_fade", offset_of!(SplitParams, floor_fade)),
                    ("altitude_length", offset_of!(SplitParams, altitude_length)),
                    ("sea_detail", offset_of!(SplitParams, sea_detail)),
                    ("vertices", offset_of!(SplitParams, vertices)),
                    ("edges", offset_of!(SplitParams, edges)),
                    ("faces", offset_of!(SplitParams, faces)),
                    ("count", offset_of!(SplitParams, count)),
                    ("row", offset_of!(SplitParams, row)),
                    ("guide_faces", offset_of!(SplitParams, guide_faces)),
                    ("guide_side", offset_of!(SplitParams, guide_side)),
                    ("_pad", offset_of!(SplitParams, _pad)),
                ],
            ),
            (
                "GuideFace",
                size_of::<GuideFace>(),
                vec![
                    ("centre", offset_of!(GuideFace, centre)),
                    ("x0", offset_of!(GuideFace, x0)),
                    ("east", offset_of!(GuideFace, east)),
                    ("y0", offset_of!(GuideFace, y0)),
                    ("north", offset_of!(GuideFace, north)),
                    ("step", offset_of!(GuideFace, step)),
                ],
            ),
            (
                "Grid",
                size_of::<ScanGrid>(),
                vec![
                    ("items", offset_of!(ScanGrid, items)),
                    ("row", offset_of!(ScanGrid, row)),
                    ("blocks", offset_of!(ScanGrid, blocks)),
                    ("block_row", offset_of!(ScanGrid, block_row)),
                ],
            ),
        ];
        let wgsl = wgsl_structs();
        let names: Vec<&str> = wgsl.iter().map(|(n, ..)| n.as_str()).collect();
        assert_eq!(names.len(), twins.len(), "layout.wgsl declares {names:?}; each needs a twin here");
        for (name, size, members) in &twins {
            let (_, span, found) = wgsl.iter().find(|(n, ..)| n == name).unwrap_or_else(|| panic!("no {name}"));
            assert_eq!(span, size, "{name}: WGSL size {span}, Rust {size}");
            let found: Vec<(&str, usize)> = found.iter().map(|(n, o)| (n.as_str(), *o)).collect();
            assert_eq!(&found, members, "{name}: WGSL members vs Rust offsets");
        }
        // The packed words: a vertex's tangent (3 bytes) then flags; an edge's level (u16),
        // kind, land.
        assert_eq!(offset_of!(Vertex, flags), offset_of!(Vertex, tangent) + 3);
        assert_eq!(offset_of!(Edge, kind), offset_of!(Edge, level) + 2);
        assert_eq!(offset_of!(Edge, land), offset_of!(Edge, level) + 3);
    }
}
