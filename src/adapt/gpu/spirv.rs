//! The adaption shaders as SPIR-V that forbids fused multiply-adds (reproducibility, paper §3.1).
//!
//! WGSL lets a compiler contract `a * b + c` into one rounding; NVIDIA's does, so positions on
//! such a device drift from the CPU's in the last bit and, through them, a split decision can
//! flip. SPIR-V can forbid it: an arithmetic instruction decorated `NoContraction` "cannot be
//! combined with another instruction", nor reassociated. On Vulkan the shaders are therefore
//! compiled here with naga (the compiler wgpu itself uses), every float addition, subtraction,
//! multiplication, division and dot product is decorated `NoContraction`, and the module is
//! handed to the driver as is (wgpu's passthrough shaders), with bind group layouts derived from
//! the same naga module, as wgpu derives them. Elsewhere the WGSL goes through wgpu unchanged.

use std::borrow::Cow;

/// `OpDecorate`.
const OP_DECORATE: u32 = 71;
/// The decoration `NoContraction`.
const NO_CONTRACTION: u32 = 42;
/// Float arithmetic with a result id: `OpFAdd`, `OpFSub`, `OpFMul`, `OpFDiv`, `OpFRem`, `OpFMod`,
/// `OpVectorTimesScalar`, `OpMatrixTimesScalar`, `OpVectorTimesMatrix`, `OpMatrixTimesVector`,
/// `OpMatrixTimesMatrix`, `OpOuterProduct`, `OpDot`.
const FLOAT_ARITHMETIC: [u32; 13] = [129, 131, 133, 136, 140, 141, 142, 143, 144, 145, 146, 147, 148];
/// The annotation section: `OpDecorate` .. `OpGroupMemberDecorate`, `OpDecorateId`,
/// `OpDecorateString`, `OpMemberDecorateString`.
const ANNOTATIONS: [u32; 8] = [71, 72, 73, 74, 75, 332, 5632, 5633];
/// `OpTypeVoid` .. `OpTypeForwardPointer`: the section after the annotations.
const TYPES: std::ops::RangeInclusive<u32> = 19..=39;
/// Words of the SPIR-V header.
const HEADER: usize = 5;
/// The workgroup variables the shaders may declare: each invocation writes its own element of
/// the scan's `part` (`shaders/adapt/scan.wgsl`) before the barrier that precedes any read, so
/// the modules skip WGSL's zero-fill of workgroup memory (naga's polyfill, one invocation
/// storing the whole array behind a barrier, tripled the split-list compaction on lavapipe).
const WRITTEN_BEFORE_READ: [&str; 1] = ["part"];

/// An entry point of a compiled stage: its own SPIR-V module (one entry point each, as wgpu
/// compiles them) and the bind group 0 it uses.
pub(crate) struct Entry {
    pub name: String,
    pub workgroup_size: [u32; 3],
    pub words: Vec<u32>,
    pub bindings: Vec<wgpu::BindGroupLayoutEntry>,
}

/// Compiles `source` (WGSL) to SPIR-V with every float operation decorated `NoContraction`, one
/// module per entry point.
pub(crate) fn compile(source: &str) -> Result<Vec<Entry>, String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::FLOAT64)
        .validate(&module)
        .map_err(|e| e.emit_to_string(source))?;
    let unchecked = module.global_variables.iter().find(|(_, var)| {
        var.space == naga::AddressSpace::WorkGroup
            && !WRITTEN_BEFORE_READ.contains(&var.name.as_deref().unwrap_or_default())
    });
    if let Some((_, var)) = unchecked {
        return Err(format!(
            "workgroup variable {:?} is not known to be written before it is read (zero-fill is skipped)",
            var.name
        ));
    }
    module
        .entry_points
        .iter()
        .enumerate()
        .map(|(i, ep)| {
            let uses = info.get_entry_point(i);
            let mut bindings: Vec<wgpu::BindGroupLayoutEntry> = module
                .global_variables
                .iter()
                .filter(|(handle, _)| !uses[*handle].is_empty())
                .filter_map(|(_, var)| {
                    let binding = var.binding.as_ref().filter(|b| b.group == 0)?;
                    let ty = match var.space {
                        naga::AddressSpace::Uniform => wgpu::BufferBindingType::Uniform,
                        naga::AddressSpace::Storage { access } => {
                            wgpu::BufferBindingType::Storage { read_only: !access.contains(naga::StorageAccess::STORE) }
                        }
                        _ => return None,
                    };
                    Some(wgpu::BindGroupLayoutEntry {
                        binding: binding.binding,
                        visibility: wgpu::ShaderStages::COMPUTE,
                        ty: wgpu::BindingType::Buffer { ty, has_dynamic_offset: false, min_binding_size: None },
                        count: None,
                    })
                })
                .collect();
            bindings.sort_by_key(|b| b.binding);
            let pipeline = naga::back::spv::PipelineOptions { shader_stage: ep.stage, entry_point: ep.name.clone() };
            let options = options(&bindings);
            let mut words =
                naga::back::spv::write_vec(&module, &info, &options, Some(&pipeline)).map_err(|e| e.to_string())?;
            forbid_contraction(&mut words)?;
            Ok(Entry { name: ep.name.clone(), workgroup_size: ep.workgroup_size, words, bindings })
        })
        .collect()
}

/// naga's SPIR-V options for an entry point binding `bindings` (sorted) in group 0.
fn options(bindings: &[wgpu::BindGroupLayoutEntry]) -> naga::back::spv::Options<'static> {
    // wgpu's Vulkan backend numbers a bind group's descriptors consecutively, in the order of
    // the layout's entries (sorted by binding), and compiles its own shaders with that map.
    let binding_map = bindings
        .iter()
        .enumerate()
        .map(|(k, b)| {
            let target =
                naga::back::spv::BindingInfo { descriptor_set: 0, binding: k as u32, binding_array_size: None };
            (naga::ResourceBinding { group: 0, binding: b.binding }, target)
        })
        .collect();
    naga::back::spv::Options {
        flags: naga::back::spv::WriterFlags::empty(),
        binding_map,
        fake_missing_bindings: false,
        // Indices are clamped into their arrays and buffers whatever the device's robustness
        // features, as wgpu does where the device has none.
        bounds_check_policies: naga::proc::BoundsCheckPolicies {
            index: naga::proc::BoundsCheckPolicy::Restrict,
            buffer: naga::proc::BoundsCheckPolicy::Restrict,
            image_load: naga::proc::BoundsCheckPolicy::Restrict,
            binding_array: naga::proc::BoundsCheckPolicy::Unchecked,
        },
        zero_initialize_workgroup_memory: naga::back::spv::ZeroInitializeWorkgroupMemoryMode::None,
        ..Default::default()
    }
}

/// The instructions of a SPIR-V module after its header: each one's first word index and its
/// words (opcode and word count in the first), or where the module is malformed.
fn instructions(words: &[u32]) -> Result<Vec<(usize, &[u32])>, String> {
    let mut found = Vec::new();
    let mut at = HEADER;
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if count == 0 || at + count > words.len() {
            return Err(format!("malformed SPIR-V instruction at word {at}"));
        }
        found.push((at, &words[at..at + count]));
        at += count;
    }
    Ok(found)
}

/// Decorates the result of every float arithmetic instruction in `words` `NoContraction`,
/// inserting the decorations at the end of the annotation section; returns how many.
pub(crate) fn forbid_contraction(words: &mut Vec<u32>) -> Result<usize, String> {
    let mut results = Vec::new();
    let mut after_annotations = None;
    let mut first_type = None;
    for (at, inst) in instructions(words)? {
        let opcode = inst[0] & 0xffff;
        if ANNOTATIONS.contains(&opcode) {
            after_annotations = Some(at + inst.len());
        } else if TYPES.contains(&opcode) && first_type.is_none() {
            first_type = Some(at);
        } else if FLOAT_ARITHMETIC.contains(&opcode) && inst.len() > 2 {
            results.push(inst[2]);
        }
    }
    let insert = after_annotations.or(first_type).ok_or("SPIR-V module without annotations or types")?;
    let decorations: Vec<u32> = results.iter().flat_map(|&id| [3 << 16 | OP_DECORATE, id, NO_CONTRACTION]).collect();
    words.splice(insert..insert, decorations);
    Ok(results.len())
}

/// The result ids decorated `NoContraction` and those of float arithmetic in `words`.
#[cfg(test)]
pub(crate) fn contraction_report(words: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let (mut decorated, mut arithmetic) = (Vec::new(), Vec::new());
    for (_, inst) in instructions(words).expect("a well-formed module") {
        let opcode = inst[0] & 0xffff;
        if opcode == OP_DECORATE && inst.len() == 3 && inst[2] == NO_CONTRACTION {
            decorated.push(inst[1]);
        } else if FLOAT_ARITHMETIC.contains(&opcode) {
            arithmetic.push(inst[2]);
        }
    }
    (decorated, arithmetic)
}

impl Entry {
    /// The passthrough descriptor of this entry point's module.
    pub(crate) fn descriptor<'a>(&'a self, label: &'a str) -> wgpu::ShaderModuleDescriptorPassthrough<'a> {
        let [x, y, z] = self.workgroup_size;
        let entry =
            wgpu::PassthroughShaderEntryPoint { name: Cow::Borrowed(self.name.as_str()), workgroup_size: (x, y, z) };
        wgpu::ShaderModuleDescriptorPassthrough {
            label: Some(label),
            entry_points: Cow::Owned(vec![entry]),
            spirv: Some(Cow::Borrowed(&self.words)),
            ..Default::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn split_stage() -> Entry {
        let mut entries = compile(&super::super::shaders::source(super::super::Stage::Split)).unwrap();
        assert_eq!(entries.len(), 1);
        entries.pop().unwrap()
    }

    #[test]
    fn every_float_operation_of_the_splits_is_decorated_no_contraction() {
        let compiled = split_stage();
        let (mut decorated, mut arithmetic) = contraction_report(&compiled.words);
        // The terrain of a split (eq. 2, 7-12) is over a hundred f64 operations.
        assert!(arithmetic.len() > 100, "{} float operations", arithmetic.len());
        decorated.sort_unstable();
        arithmetic.sort_unstable();
        assert_eq!(decorated, arithmetic);
        // Decorating again finds the same operations and adds them once more, nothing else moves.
        let mut again = compiled.words.clone();
        assert_eq!(forbid_contraction(&mut again), Ok(arithmetic.len()));
        assert_eq!(again.len(), compiled.words.len() + 3 * arithmetic.len());
        assert_eq!(&again[..HEADER], &compiled.words[..HEADER]);
    }

    #[test]
    fn bind_group_layouts_follow_the_shader() {
        let split = split_stage();
        assert_eq!(split.name, "split_edges");
        assert_eq!(split.workgroup_size, [64, 1, 1]);
        let kinds: Vec<(u32, wgpu::BufferBindingType)> = split
            .bindings
            .iter()
            .map(|b| match b.ty {
                wgpu::BindingType::Buffer { ty, .. } => (b.binding, ty),
                other => panic!("binding {}: {other:?}", b.binding),
            })
            .collect();
        let rw = wgpu::BufferBindingType::Storage { read_only: false };
        let ro = wgpu::BufferBindingType::Storage { read_only: true };
        let uniform = wgpu::BufferBindingType::Uniform;
        assert_eq!(kinds, [(0, rw), (1, rw), (2, rw), (3, ro), (4, uniform), (5, ro), (6, ro)]);
    }

    #[test]
    fn descriptors_are_numbered_as_wgpu_numbers_them_on_vulkan() {
        let source = super::super::shaders::source(super::super::Stage::State);
        let entries = compile(&source).unwrap();
        let candidates = entries.iter().find(|e| e.name == "collapse_candidates").unwrap();
        let wgsl: Vec<u32> = candidates.bindings.iter().map(|b| b.binding).collect();
        assert_eq!(wgsl, [0, 1, 2, 4, 5, 6, 7, 8]);
        // `OpDecorate %id Binding n` (decoration 33): n runs over 0..8 without the hole.
        let mut numbers: Vec<u32> = instructions(&candidates.words)
            .unwrap()
            .into_iter()
            .filter(|(_, inst)| inst[0] & 0xffff == OP_DECORATE && inst.len() == 4 && inst[2] == 33)
            .map(|(_, inst)| inst[3])
            .collect();
        numbers.sort_unstable();
        assert_eq!(numbers, (0..8).collect::<Vec<u32>>());
    }

    #[test]
    fn malformed_modules_are_refused() {
        let mut words = split_stage().words;
        words.truncate(HEADER + 1);
        words[HEADER] = 40 << 16 | OP_DECORATE;
        assert!(forbid_contraction(&mut words).is_err());
        let mut empty = vec![0x0723_0203, 0x0001_0000, 0, 1, 0];
        assert!(forbid_contraction(&mut empty).is_err());
        assert!(compile("fn broken( {").is_err());
        let reads_unwritten = "var<workgroup> total: atomic<u32>;\n\
            @compute @workgroup_size(64) fn count() { atomicAdd(&total, 1u); }";
        let refused = compile(reads_unwritten).err().unwrap();
        assert!(refused.contains("\"total\""), "{refused}");
        assert!(compile(&reads_unwritten.replace("total", "part")).is_ok());
    }
}
