//! BVH motion export: the skeleton with its real offsets, the motion at the simulated frame
//! rate.
//!
//! Units are centimetres (the usual BVH scale; Blender's importer scales on import). The
//! root `pelvis` has six channels, `Xposition Yposition Zposition Zrotation Xrotation
//! Yrotation`, with OFFSET 0 so its position channels are its world position; every other
//! joint has `Zrotation Xrotation Yrotation`: its rotation relative to its parent is
//! Rz · Rx · Ry (degrees), applied to its rest offset frame. Axes are the model's: x forward,
//! y up, z right. Leaf bones end in an `End Site` at their tip (head top, finger tips, toe
//! tips).

use crate::model::body::{BodyDims, Bone, Pose};
use glam::EulerRot;
use std::io::{self, Write};

const CM: f64 = 100.0;

fn children(bone: Bone) -> impl Iterator<Item = Bone> {
    Bone::ALL.into_iter().filter(move |b| b.parent() == Some(bone))
}

fn write_joint(out: &mut dyn Write, dims: &BodyDims, bone: Bone, depth: usize) -> io::Result<()> {
    let pad = "  ".repeat(depth);
    let o = if bone.parent().is_some() { dims.rest_offset(bone) * CM } else { glam::DVec3::ZERO };
    if bone.parent().is_none() {
        writeln!(out, "ROOT {}", bone.name())?;
    } else {
        writeln!(out, "{pad}JOINT {}", bone.name())?;
    }
    writeln!(out, "{pad}{{")?;
    writeln!(out, "{pad}  OFFSET {:.6} {:.6} {:.6}", o.x, o.y, o.z)?;
    if bone.parent().is_none() {
        writeln!(out, "{pad}  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation")?;
    } else {
        writeln!(out, "{pad}  CHANNELS 3 Zrotation Xrotation Yrotation")?;
    }
    let mut any = false;
    for child in children(bone) {
        any = true;
        write_joint(out, dims, child, depth + 1)?;
    }
    if !any {
        let e = dims.end_offset(bone) * CM;
        writeln!(out, "{pad}  End Site")?;
        writeln!(out, "{pad}  {{")?;
        writeln!(out, "{pad}    OFFSET {:.6} {:.6} {:.6}", e.x, e.y, e.z)?;
        writeln!(out, "{pad}  }}")?;
    }
    writeln!(out, "{pad}}}")
}

/// Joints in the order their channels appear in a MOTION line (depth first).
fn channel_order() -> Vec<Bone> {
    fn visit(bone: Bone, order: &mut Vec<Bone>) {
        order.push(bone);
        for c in children(bone) {
            visit(c, order);
        }
    }
    let mut order = Vec::new();
    visit(Bone::Pelvis, &mut order);
    order
}

/// Writes the HIERARCHY and the MOTION header for `frames` frames at `fps`.
pub(crate) fn write_header(out: &mut dyn Write, dims: &BodyDims, frames: usize, fps: f64) -> io::Result<()> {
    writeln!(out, "HIERARCHY")?;
    write_joint(out, dims, Bone::Pelvis, 0)?;
    writeln!(out, "MOTION")?;
    writeln!(out, "Frames: {frames}")?;
    writeln!(out, "Frame Time: {:.8}", 1.0 / fps)
}

/// Writes one MOTION line for `pose`.
pub(crate) fn write_frame(out: &mut dyn Write, pose: &Pose, line: &mut String) -> io::Result<()> {
    use std::fmt::Write as _;
    line.clear();
    for bone in channel_order() {
        if bone.parent().is_none() {
            let p = pose.pos(bone) * CM;
            let _ = write!(line, "{:.4} {:.4} {:.4} ", p.x, p.y, p.z);
        }
        let (z, x, y) = pose.local_rotation(bone).to_euler(EulerRot::ZXY);
        let _ = write!(line, "{:.4} {:.4} {:.4} ", z.to_degrees(), x.to_degrees(), y.to_degrees());
    }
    let trimmed = line.trim_end();
    writeln!(out, "{trimmed}")
}
