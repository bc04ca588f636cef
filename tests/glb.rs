//! The report's `walk.glb` read back by an independent reader (the `gltf` crate, which checks
//! the JSON against the glTF 2.0 schema and its index rules as it reads): the container's
//! layout, the skeleton, the skin and its mesh, and the animation turned back into joint
//! positions by composing node transforms — every joint within 1 mm of the recorded pose at
//! every frame, on the default walk and on stairs.

use gaitlab::analysis::{Keep, Recording};
use gaitlab::model::body::{Bone, Pose};
use glam::{DMat4, DQuat, DVec3};
use std::path::{Path, PathBuf};
use std::process::Command;

const CYCLES: u32 = 4;

fn report(config: &str) -> (Vec<u8>, PathBuf) {
    let dir = std::env::temp_dir().join(format!("gaitlab-glb-{config}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(["report", &format!("configs/{config}.toml"), "--out", dir.to_str().unwrap()])
        .args(["--cycles", &CYCLES.to_string()])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    (std::fs::read(dir.join("walk.glb")).expect("walk.glb in the report"), dir)
}

fn record(config: &str) -> Recording {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("configs/{config}.toml"));
    let params = gaitlab::config::load(&path, &[]).unwrap();
    gaitlab::analysis::record(&params, f64::from(CYCLES), params.sim.fps, Keep::ALL).unwrap()
}

fn word(bytes: &[u8], at: usize) -> usize {
    u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize
}

/// The GLB container by hand: header, a JSON chunk padded with spaces, a BIN chunk padded
/// with zeros, both 4-byte aligned, and every bufferView on a 4-byte boundary inside it.
fn check_container(glb: &[u8]) {
    assert_eq!(&glb[0..4], b"glTF");
    assert_eq!(word(glb, 4), 2, "GLB version");
    assert_eq!(word(glb, 8), glb.len(), "the header's length is the file's");
    let json_len = word(glb, 12);
    assert_eq!(&glb[16..20], b"JSON");
    assert_eq!(json_len % 4, 0);
    let json_chunk = &glb[20..20 + json_len];
    let text = std::str::from_utf8(json_chunk).unwrap();
    let json: serde_json::Value = serde_json::from_str(text.trim_end_matches(' ')).expect("JSON chunk");
    let bin_at = 20 + json_len;
    let bin_len = word(glb, bin_at);
    assert_eq!(&glb[bin_at + 4..bin_at + 8], b"BIN\0");
    assert_eq!(bin_len % 4, 0);
    assert_eq!(bin_at + 8 + bin_len, glb.len(), "nothing after the BIN chunk");
    let buffer_len = json["buffers"][0]["byteLength"].as_u64().unwrap() as usize;
    assert!(buffer_len <= bin_len && bin_len - buffer_len < 4, "buffer {buffer_len} in a chunk of {bin_len}");
    assert!(glb[bin_at + 8 + buffer_len..].iter().all(|&b| b == 0), "BIN padding is zeros");
    for view in json["bufferViews"].as_array().unwrap() {
        let offset = view["byteOffset"].as_u64().unwrap() as usize;
        assert_eq!(offset % 4, 0, "{view}");
        assert!(offset + view["byteLength"].as_u64().unwrap() as usize <= buffer_len, "{view}");
    }
}

/// A node's rest transform as (translation, rotation), which must have no scale.
fn rest_transform(node: &gltf::Node) -> (DVec3, DQuat) {
    let (t, r, s) = node.transform().decomposed();
    assert_eq!(s, [1.0; 3], "{:?} is scaled", node.name());
    (to_vec(t), to_quat(r))
}

fn to_vec(v: [f32; 3]) -> DVec3 {
    DVec3::new(v[0].into(), v[1].into(), v[2].into())
}

fn to_quat(q: [f32; 4]) -> DQuat {
    DQuat::from_xyzw(q[0].into(), q[1].into(), q[2].into(), q[3].into())
}

/// Each node's parent, read from the nodes' children lists.
fn parents(doc: &gltf::Document) -> Vec<Option<usize>> {
    let mut parent = vec![None; doc.nodes().len()];
    for node in doc.nodes() {
        for child in node.children() {
            assert!(parent[child.index()].is_none(), "node {} has two parents", child.index());
            // Parents first, so that a pass in index order composes transforms.
            assert!(node.index() < child.index(), "parent after child");
            parent[child.index()] = Some(node.index());
        }
    }
    parent
}

/// World (position, rotation) of every node from local (translation, rotation) pairs:
/// world = parent world · T · R, as glTF composes node transforms.
fn compose(local: &[(DVec3, DQuat)], parent: &[Option<usize>]) -> Vec<(DVec3, DQuat)> {
    let mut world: Vec<(DVec3, DQuat)> = Vec::with_capacity(local.len());
    for (i, &(t, r)) in local.iter().enumerate() {
        world.push(match parent[i] {
            None => (t, r),
            Some(p) => (world[p].0 + world[p].1 * t, world[p].1 * r),
        });
    }
    world
}

/// Per node, its keyed translations and rotations (empty where not animated), after checking
/// the clip's samplers: LINEAR, keyed at `frame / fps`, as many keys as frames.
fn keyframes(doc: &gltf::Document, blob: &[u8], frames: usize, fps: f64) -> Vec<(Vec<DVec3>, Vec<DQuat>)> {
    use gltf::animation::util::ReadOutputs;
    let mut keys = vec![(Vec::new(), Vec::new()); doc.nodes().len()];
    assert_eq!(doc.animations().len(), 1, "one clip");
    let clip = doc.animations().next().unwrap();
    assert_eq!(clip.name(), Some("walk"));
    assert_eq!(clip.channels().count(), Bone::ALL.len() + 1, "a rotation per bone and the root's translation");
    for channel in clip.channels() {
        assert_eq!(channel.sampler().interpolation(), gltf::animation::Interpolation::Linear);
        let reader = channel.reader(|b| (b.index() == 0).then_some(blob));
        let times: Vec<f32> = reader.read_inputs().unwrap().collect();
        assert_eq!(times.len(), frames);
        for (i, t) in times.iter().enumerate() {
            assert!((f64::from(*t) - i as f64 / fps).abs() < 1e-6, "key {i} at {t} s");
        }
        let node = &mut keys[channel.target().node().index()];
        match reader.read_outputs().unwrap() {
            ReadOutputs::Translations(t) => node.0 = t.map(to_vec).collect(),
            ReadOutputs::Rotations(r) => node.1 = r.into_f32().map(to_quat).collect(),
            _ => panic!("only translations and rotations are animated"),
        }
        assert!(node.0.len() == frames || node.1.len() == frames, "a sampler with a key per frame");
    }
    for (i, (_, rotations)) in keys.iter().enumerate().take(Bone::ALL.len()) {
        assert_eq!(rotations.len(), frames, "node {i} has no rotation channel");
        assert!(rotations.iter().all(|q| (q.length() - 1.0).abs() < 1e-6), "unit quaternions");
        assert!(rotations.windows(2).all(|w| w[0].dot(w[1]) >= 0.0), "consecutive keys in one hemisphere");
    }
    keys
}

/// The skin: every bone node a joint, bound in the rest pose (each inverse bind matrix undoes
/// its joint's rest world transform), and its mesh's vertices each weighted wholly to one bone.
/// Returns the inverse bind matrices and the mesh's (bone, rest position) pairs.
fn check_skin(doc: &gltf::Document, blob: &[u8], rest: &[(DVec3, DQuat)]) -> (Vec<DMat4>, Vec<(usize, DVec3)>) {
    let get = |b: gltf::Buffer| (b.index() == 0).then_some(blob);
    let skin = doc.skins().next().expect("a skin");
    let joints: Vec<usize> = skin.joints().map(|j| j.index()).collect();
    assert_eq!(joints, (0..Bone::ALL.len()).collect::<Vec<_>>());
    assert_eq!(skin.skeleton().map(|n| n.index()), Some(Bone::Pelvis.index()));
    let ibm: Vec<DMat4> = skin
        .reader(get)
        .read_inverse_bind_matrices()
        .unwrap()
        .map(|m| DMat4::from_cols_array_2d(&m.map(|c| c.map(f64::from))))
        .collect();
    assert_eq!(ibm.len(), joints.len());
    for (j, m) in ibm.iter().enumerate() {
        let bind = DMat4::from_rotation_translation(rest[j].1, rest[j].0);
        assert!((*m * bind).abs_diff_eq(DMat4::IDENTITY, 1e-5), "joint {j}: IBM is not the inverse of the bind pose");
    }
    let mesh_node = doc.nodes().find(|n| n.skin().is_some()).expect("a skinned node");
    assert!(doc.default_scene().unwrap().nodes().any(|n| n.index() == mesh_node.index()), "skinned mesh at the root");
    let primitive = mesh_node.mesh().expect("a mesh").primitives().next().unwrap();
    let reader = primitive.reader(get);
    let positions: Vec<DVec3> = reader.read_positions().unwrap().map(to_vec).collect();
    let bones: Vec<[u16; 4]> = reader.read_joints(0).unwrap().into_u16().collect();
    let weights: Vec<[f32; 4]> = reader.read_weights(0).unwrap().into_f32().collect();
    assert_eq!(reader.read_normals().unwrap().count(), positions.len());
    assert!(positions.len() >= 3 * 8 * Bone::ALL.len(), "a double pyramid a bone at least");
    assert!(bones.len() == positions.len() && weights.len() == positions.len());
    assert!(weights.iter().all(|w| *w == [1.0, 0.0, 0.0, 0.0]));
    let vertices: Vec<(usize, DVec3)> = bones.iter().map(|b| usize::from(b[0])).zip(positions).collect();
    for b in 0..Bone::ALL.len() {
        assert!(vertices.iter().any(|v| v.0 == b), "bone {b} has no vertices");
    }
    (ibm, vertices)
}

/// Every joint rebuilt from the file against the recorded pose, every frame; and the mesh
/// skinned as an importer skins it (joint world · inverse bind · vertex) against the same
/// point carried by the recorded bone. Returns the worst joint and vertex distances (m).
fn round_trip(glb: &[u8], poses: &[Pose], fps: f64) -> (f64, f64) {
    let gltf = gltf::Gltf::from_slice(glb).expect("a valid glTF 2.0 binary");
    let blob = gltf.blob.as_deref().expect("a BIN chunk");
    let nodes: Vec<gltf::Node> = gltf.nodes().collect();
    assert_eq!(nodes.len(), Bone::ALL.len() + 1, "a node per bone and the mesh's");
    let bones: Vec<Bone> = nodes[..Bone::ALL.len()]
        .iter()
        .map(|n| *Bone::ALL.iter().find(|b| Some(b.name()) == n.name()).unwrap_or_else(|| panic!("{:?}", n.name())))
        .collect();
    let parent = parents(&gltf);
    let rest_local: Vec<(DVec3, DQuat)> = nodes.iter().map(rest_transform).collect();
    let rest = compose(&rest_local, &parent);
    let (ibm, vertices) = check_skin(&gltf, blob, &rest);
    let keys = keyframes(&gltf, blob, poses.len(), fps);
    let (mut worst_joint, mut worst_vertex) = (0.0f64, 0.0f64);
    for (i, pose) in poses.iter().enumerate() {
        let local: Vec<(DVec3, DQuat)> = rest_local
            .iter()
            .zip(&keys)
            .map(|(&(t, r), (ts, rs))| (ts.get(i).copied().unwrap_or(t), rs.get(i).copied().unwrap_or(r)))
            .collect();
        let world = compose(&local, &parent);
        for (k, bone) in bones.iter().enumerate() {
            worst_joint = worst_joint.max(world[k].0.distance(pose.pos(*bone)));
        }
        if i % 10 == 0 {
            for &(k, v) in &vertices {
                let skinned = DMat4::from_rotation_translation(world[k].1, world[k].0) * ibm[k];
                let carried = pose.point(bones[k], v - rest[k].0);
                worst_vertex = worst_vertex.max(skinned.transform_point3(v).distance(carried));
            }
        }
    }
    (worst_joint, worst_vertex)
}

#[test]
fn walk_glb_round_trips_through_the_gltf_crate_to_within_a_millimetre() {
    for config in ["default", "stairs_up"] {
        let (glb, dir) = report(config);
        let run = record(config);
        // The report's walk, written by the library's writer, the same bytes each time.
        let dims = &run.gait.resolved().dims;
        assert_eq!(glb, gaitlab::output::gltf::glb(dims, &run.poses, run.fps), "{config}: not the recorded walk");
        assert_eq!(glb, gaitlab::output::gltf::glb(dims, &run.poses, run.fps));
        check_container(&glb);
        let (joint, vertex) = round_trip(&glb, &run.poses, run.fps);
        eprintln!(
            "{config}: glTF round trip over {} frames: worst joint {:.4} mm, worst skinned vertex {:.4} mm",
            run.poses.len(),
            joint * 1e3,
            vertex * 1e3
        );
        assert!(joint < 0.001, "{config}: worst joint {:.3} mm", joint * 1e3);
        assert!(vertex < 0.001, "{config}: worst skinned vertex {:.3} mm", vertex * 1e3);
        std::fs::remove_dir_all(dir).unwrap();
    }
}
