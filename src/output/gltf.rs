//! glTF 2.0 export (`walk.glb`): the BVH's skeleton as a skinned armature with the walk as
//! one animation clip, in the binary container Blender, three.js and game engines import
//! directly.
//!
//! What is in the file:
//!
//! - One node per [`Bone`], in [`Bone::ALL`] order (node `i` is the bone of index `i`), named
//!   as in the BVH (`thigh_r`), its rest translation the BVH OFFSET (the bone's joint from its
//!   parent's joint; the root's is the standing pelvis position), no rest rotation. The bind
//!   pose is the model's rest pose.
//! - A skin over those nodes (`skeleton` = the pelvis), its inverse bind matrices the rest
//!   pose's, and a small mesh skinned to it (node `walker`, at the scene's root as the spec
//!   asks of skinned meshes) so that importers show a figure and treat the nodes as an
//!   armature: a thin double pyramid from each joint to each child joint (to the bone's end
//!   for the head, hands and toes), every vertex weighted 1.0 to its bone.
//! - One animation, `walk`: the pelvis translation and every bone's rotation relative to its
//!   parent (the BVH's channels as quaternions), one sampler per channel, LINEAR, keyed at
//!   every recorded frame (times `frame / fps` s, shared by all samplers). Consecutive
//!   quaternions are kept in one hemisphere so that interpolation between frames takes the
//!   short way.
//!
//! Units are metres and seconds. Axes are the model's (x forward, y up, z right; right-handed,
//! as glTF is), so the joint positions are the joint table's. glTF's convention is y up with
//! the asset's front facing +z (its right is −x): the walker here faces +x, which is that
//! convention turned −90° about y. Importers do not rotate for it: Blender's (which turns y up
//! into its z up) shows the walk along its +X, three.js along +x.
//!
//! Bytes are deterministic: the JSON is built with `serde_json` (sorted keys) and the buffer
//! from the poses alone. Layout per the spec's GLB rules: a 12-byte header, a JSON chunk
//! padded with spaces and a BIN chunk padded with zeros, both to 4 bytes; every bufferView
//! starts on a 4-byte boundary. Validated by `tests/report.rs`, which reads the file back
//! with the `gltf` crate and rebuilds the joint positions from it.

use crate::model::body::{BodyDims, Bone, Pose};
use glam::{DQuat, DVec3};
use serde_json::{Value, json};
use std::io::{self, Write};

/// glTF component type FLOAT.
const FLOAT: u32 = 5126;
/// glTF component type UNSIGNED_BYTE.
const UNSIGNED_BYTE: u32 = 5121;
/// bufferView target ARRAY_BUFFER (vertex attributes).
const ARRAY_BUFFER: u32 = 34962;
/// Node index of the skinned mesh, after the bones.
const MESH_NODE: usize = Bone::ALL.len();

/// The binary buffer with the JSON's bufferViews and accessors built beside it.
#[derive(Default)]
struct Buffer {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Buffer {
    /// Appends a bufferView of `length` bytes, starting on a 4-byte boundary, which `fill`
    /// writes at the end of the buffer; returns its index.
    fn view(&mut self, length: usize, target: Option<u32>, fill: impl FnOnce(&mut Vec<u8>)) -> usize {
        self.bin.resize(self.bin.len().next_multiple_of(4), 0);
        let mut view = json!({ "buffer": 0, "byteOffset": self.bin.len(), "byteLength": length });
        if let Some(t) = target {
            view["target"] = json!(t);
        }
        let start = self.bin.len();
        fill(&mut self.bin);
        debug_assert_eq!(self.bin.len() - start, length);
        self.views.push(view);
        self.views.len() - 1
    }

    /// An accessor of FLOAT elements of `width` components (`kind`: SCALAR, VEC3, VEC4,
    /// MAT4), in a bufferView of its own; with `bounds`, the per-component min and max the
    /// spec requires of positions and animation times.
    fn floats(&mut self, data: &[f32], kind: &str, width: usize, target: Option<u32>, bounds: bool) -> usize {
        let view = self.view(data.len() * 4, target, |bin| {
            for v in data {
                bin.extend_from_slice(&v.to_le_bytes());
            }
        });
        let mut accessor =
            json!({ "bufferView": view, "componentType": FLOAT, "count": data.len() / width, "type": kind });
        if bounds {
            let component = |c: usize| data.iter().skip(c).step_by(width).copied();
            let min: Vec<f32> = (0..width).map(|c| component(c).fold(f32::INFINITY, f32::min)).collect();
            let max: Vec<f32> = (0..width).map(|c| component(c).fold(f32::NEG_INFINITY, f32::max)).collect();
            accessor["min"] = json!(min);
            accessor["max"] = json!(max);
        }
        self.accessors.push(accessor);
        self.accessors.len() - 1
    }

    /// A VEC4 accessor of UNSIGNED_BYTE vertex attributes (JOINTS_0).
    fn bytes4(&mut self, data: &[u8]) -> usize {
        let view = self.view(data.len(), Some(ARRAY_BUFFER), |bin| bin.extend_from_slice(data));
        self.accessors.push(json!({
            "bufferView": view, "componentType": UNSIGNED_BYTE, "count": data.len() / 4, "type": "VEC4"
        }));
        self.accessors.len() - 1
    }
}

/// Pushes a vector's components as `f32`.
fn push3(out: &mut Vec<f32>, v: DVec3) {
    out.extend([v.x as f32, v.y as f32, v.z as f32]);
}

/// The walk as a binary glTF 2.0 file: `dims`' skeleton, animated through `poses` (one per
/// frame, at `fps`). See the module doc for what it holds.
#[must_use]
pub fn glb(dims: &BodyDims, poses: &[Pose], fps: f64) -> Vec<u8> {
    let mut out = Vec::new();
    write_glb(&mut out, dims, poses, fps).expect("writing to memory does not fail");
    out
}

/// Writes [`glb`]'s bytes to `out` without holding a second copy of the buffer (23 MB at the
/// report's 1 000 cycles).
pub fn write_glb(out: &mut dyn Write, dims: &BodyDims, poses: &[Pose], fps: f64) -> io::Result<()> {
    // The keys' bytes (a time, the root's translation and a quaternion a bone, each frame)
    // reserved at once, beside room for the mesh: no doubling of a large buffer as it grows.
    let key_bytes = poses.len() * 4 * (1 + 3 + 4 * Bone::ALL.len());
    let mut buffer = Buffer { bin: Vec::with_capacity(key_bytes + (1 << 16)), ..Buffer::default() };
    let skin = skin(&mut buffer, dims);
    let mesh = mesh(&mut buffer, dims);
    // No frames, no clip: an accessor must hold at least one element.
    let animation = (!poses.is_empty()).then(|| animation(&mut buffer, poses, fps));
    let mut nodes = bone_nodes(dims);
    nodes.push(json!({ "name": "walker", "mesh": 0, "skin": 0 }));
    let mut document = json!({
        "asset": { "version": "2.0", "generator": concat!("gaitlab ", env!("CARGO_PKG_VERSION")) },
        "scene": 0,
        "scenes": [{ "name": "walk", "nodes": [Bone::Pelvis.index(), MESH_NODE] }],
        "nodes": nodes,
        "skins": [skin],
        "meshes": [mesh],
        "materials": [{
            "name": "bone",
            "pbrMetallicRoughness": { "baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.7 }
        }],
        "accessors": buffer.accessors,
        "bufferViews": buffer.views,
        "buffers": [{ "byteLength": buffer.bin.len() }],
    });
    if let Some(clip) = animation {
        document["animations"] = json!([clip]);
    }
    let json = serde_json::to_vec(&document).map_err(io::Error::other)?;
    container(out, json, buffer.bin)
}

/// The GLB container: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros).
fn container(out: &mut dyn Write, mut json: Vec<u8>, mut bin: Vec<u8>) -> io::Result<()> {
    json.resize(json.len().next_multiple_of(4), b' ');
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let word = |n: usize| {
        u32::try_from(n).map(u32::to_le_bytes).map_err(|_| io::Error::other("a glTF binary is limited to 4 GiB"))
    };
    out.write_all(b"glTF")?;
    out.write_all(&2u32.to_le_bytes())?;
    out.write_all(&word(total)?)?;
    out.write_all(&word(json.len())?)?;
    out.write_all(b"JSON")?;
    out.write_all(&json)?;
    out.write_all(&word(bin.len())?)?;
    out.write_all(b"BIN\0")?;
    out.write_all(&bin)
}

/// A node per bone: its name, rest translation and children.
fn bone_nodes(dims: &BodyDims) -> Vec<Value> {
    Bone::ALL
        .iter()
        .map(|&bone| {
            let t = dims.rest_offset(bone);
            let mut node = json!({ "name": bone.name(), "translation": [t.x as f32, t.y as f32, t.z as f32] });
            let children: Vec<usize> =
                Bone::ALL.iter().filter(|b| b.parent() == Some(bone)).map(|b| b.index()).collect();
            if !children.is_empty() {
                node["children"] = json!(children);
            }
            node
        })
        .collect()
}

/// The skin: the bone nodes as joints, bound in the rest pose (each inverse bind matrix the
/// translation back from the bone's rest position; rest rotations are the identity).
fn skin(buffer: &mut Buffer, dims: &BodyDims) -> Value {
    let rest = Pose::rest(dims);
    let mut matrices = Vec::with_capacity(16 * Bone::ALL.len());
    for bone in Bone::ALL {
        let p = rest.pos(bone);
        // Column-major: the translation is the fourth column.
        matrices.extend([1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
        matrices.extend([-p.x as f32, -p.y as f32, -p.z as f32, 1.0]);
    }
    let inverse_bind = buffer.floats(&matrices, "MAT4", 16, None, false);
    let joints: Vec<usize> = Bone::ALL.iter().map(|b| b.index()).collect();
    json!({ "name": "skeleton", "joints": joints, "skeleton": Bone::Pelvis.index(), "inverseBindMatrices": inverse_bind })
}

/// Where the mesh draws a segment of each bone, in the bone's frame: to each child's joint,
/// or to the bone's end for a bone without children.
fn segments(dims: &BodyDims, bone: Bone) -> Vec<DVec3> {
    let to_children: Vec<DVec3> =
        Bone::ALL.iter().filter(|b| b.parent() == Some(bone)).map(|&b| dims.rest_offset(b)).collect();
    if to_children.is_empty() { vec![dims.end_offset(bone)] } else { to_children }
}

/// Triangles (three corners each) of a thin double pyramid from `head` to `tail`, widest at
/// 15 % of its length, each corner-wound so that its face looks outward.
fn double_pyramid(head: DVec3, tail: DVec3) -> Vec<[DVec3; 3]> {
    let along = tail - head;
    let length = along.length();
    let axis = along / length;
    let helper = if axis.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u = axis.cross(helper).normalize();
    let v = axis.cross(u);
    let centre = head + 0.15 * along;
    let width = (0.1 * length).clamp(0.008, 0.03);
    let ring = [u, v, -u, -v].map(|d| centre + width * d);
    let mut faces = Vec::with_capacity(8);
    for k in 0..4 {
        let (a, b) = (ring[k], ring[(k + 1) % 4]);
        for apex in [head, tail] {
            let normal = (a - apex).cross(b - apex);
            let outward = normal.dot((apex + a + b) / 3.0 - centre) > 0.0;
            faces.push(if outward { [apex, a, b] } else { [apex, b, a] });
        }
    }
    faces
}

/// The skinned mesh: [`double_pyramid`]s along every bone's [`segments`] in the rest pose,
/// flat-shaded (three vertices a face, each with the face's normal), each vertex weighted
/// 1.0 to its bone.
fn mesh(buffer: &mut Buffer, dims: &BodyDims) -> Value {
    let rest = Pose::rest(dims);
    let (mut positions, mut normals, mut joints, mut weights) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for bone in Bone::ALL {
        for segment in segments(dims, bone) {
            if segment.length() < 1e-6 {
                continue;
            }
            let head = rest.pos(bone);
            for face in double_pyramid(head, head + segment) {
                let normal = (face[1] - face[0]).cross(face[2] - face[0]).normalize();
                for corner in face {
                    push3(&mut positions, corner);
                    push3(&mut normals, normal);
                    joints.extend([bone.index() as u8, 0, 0, 0]);
                    weights.extend([1.0f32, 0.0, 0.0, 0.0]);
                }
            }
        }
    }
    let attributes = json!({
        "POSITION": buffer.floats(&positions, "VEC3", 3, Some(ARRAY_BUFFER), true),
        "NORMAL": buffer.floats(&normals, "VEC3", 3, Some(ARRAY_BUFFER), false),
        "JOINTS_0": buffer.bytes4(&joints),
        "WEIGHTS_0": buffer.floats(&weights, "VEC4", 4, Some(ARRAY_BUFFER), false),
    });
    json!({ "name": "bones", "primitives": [{ "attributes": attributes, "material": 0, "mode": 4 }] })
}

/// The `walk` clip: the pelvis translation and each bone's rotation relative to its parent
/// at every frame, one LINEAR sampler a channel over the shared frame times.
fn animation(buffer: &mut Buffer, poses: &[Pose], fps: f64) -> Value {
    let times: Vec<f32> = (0..poses.len()).map(|i| (i as f64 / fps) as f32).collect();
    let input = buffer.floats(&times, "SCALAR", 1, None, true);
    let mut samplers = Vec::with_capacity(Bone::ALL.len() + 1);
    let mut channels = Vec::with_capacity(Bone::ALL.len() + 1);
    let mut add = |output: usize, node: usize, path: &str| {
        channels.push(json!({ "sampler": samplers.len(), "target": { "node": node, "path": path } }));
        samplers.push(json!({ "input": input, "interpolation": "LINEAR", "output": output }));
    };
    let mut root = Vec::with_capacity(3 * poses.len());
    for pose in poses {
        push3(&mut root, pose.pos(Bone::Pelvis));
    }
    add(buffer.floats(&root, "VEC3", 3, None, false), Bone::Pelvis.index(), "translation");
    for bone in Bone::ALL {
        let rotations = local_rotations(poses, bone);
        add(buffer.floats(&rotations, "VEC4", 4, None, false), bone.index(), "rotation");
    }
    json!({ "name": "walk", "channels": channels, "samplers": samplers })
}

/// `bone`'s rotation relative to its parent at every frame as `x, y, z, w`, each quaternion
/// in the hemisphere of the one before (q and −q are the same rotation; interpolating
/// between opposite signs would swing the long way round).
fn local_rotations(poses: &[Pose], bone: Bone) -> Vec<f32> {
    let mut out = Vec::with_capacity(4 * poses.len());
    let mut previous = DQuat::IDENTITY;
    for pose in poses {
        let mut q = pose.local_rotation(bone).normalize();
        if q.dot(previous) < 0.0 {
            q = -q;
        }
        previous = q;
        out.extend([q.x as f32, q.y as f32, q.z as f32, q.w as f32]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::body::Sex;

    #[test]
    fn a_walk_without_frames_has_no_clip_and_one_frame_has_one_key_a_channel() {
        let dims = BodyDims::from_height(1.75, Sex::Male);
        let empty = ::gltf::Gltf::from_slice(&glb(&dims, &[], 60.0)).expect("valid without frames");
        assert_eq!((empty.animations().count(), empty.skins().count(), empty.nodes().count()), (0, 1, 22));
        let file = glb(&dims, &[Pose::rest(&dims)], 60.0);
        let one = ::gltf::Gltf::from_slice(&file).expect("valid with one frame");
        let clip = one.animations().next().unwrap();
        assert_eq!(clip.channels().count(), 22);
        assert!(clip.samplers().all(|s| s.input().count() == 1 && s.output().count() == 1));
    }
}
