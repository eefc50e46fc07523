//! The adaption shaders of `shaders/adapt/`, pulled in here and nowhere else: each stage's
//! module is `layout.wgsl` (every layout and the shared arithmetic) followed by the stage's own
//! file and the helpers it calls — the refinement criterion (`view.wgsl`), the far end of an
//! edge (`edges.wgsl`) and the block prefix sum (`scan.wgsl`).

use super::Stage;

pub(crate) const LAYOUT: &str = include_str!("../../../shaders/adapt/layout.wgsl");
pub(crate) const STATE: &str = include_str!("../../../shaders/adapt/state.wgsl");
pub(crate) const SELECT: &str = include_str!("../../../shaders/adapt/select.wgsl");
pub(crate) const SPLIT: &str = include_str!("../../../shaders/adapt/split.wgsl");
pub(crate) const COLLAPSE: &str = include_str!("../../../shaders/adapt/collapse.wgsl");
pub(crate) const COMPACT: &str = include_str!("../../../shaders/adapt/compact.wgsl");
pub(crate) const VIEW: &str = include_str!("../../../shaders/adapt/view.wgsl");
pub(crate) const EDGES: &str = include_str!("../../../shaders/adapt/edges.wgsl");
pub(crate) const SCAN: &str = include_str!("../../../shaders/adapt/scan.wgsl");

/// The files of `stage`'s module after `layout.wgsl`, the stage's own first.
fn parts(stage: Stage) -> &'static [&'static str] {
    match stage {
        Stage::State => &[STATE, VIEW, EDGES],
        Stage::Select => &[SELECT, SCAN],
        Stage::Split => &[SPLIT, EDGES],
        Stage::Collapse => &[COLLAPSE, VIEW, EDGES],
        Stage::Compact => &[COMPACT, SCAN],
    }
}

/// The whole WGSL module of `stage`.
pub(crate) fn source(stage: Stage) -> String {
    let mut full = LAYOUT.to_string();
    for part in parts(stage) {
        full.push('\n');
        full.push_str(part);
    }
    full
}

/// The file name of `stage`'s shader, for labels and messages.
pub(crate) fn file_name(stage: Stage) -> &'static str {
    match stage {
        Stage::State => "state.wgsl",
        Stage::Select => "select.wgsl",
        Stage::Split => "split.wgsl",
        Stage::Collapse => "collapse.wgsl",
        Stage::Compact => "compact.wgsl",
    }
}
