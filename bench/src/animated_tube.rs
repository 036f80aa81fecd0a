//! A model that moves, made in memory for the animation benchmark and report: a tube of 10,000 vertices (100
//! rings of 100) along a chain of 50 joints, each vertex on the two joints nearest it, with two morph targets at
//! weights 0.3 and 0.1, and one animation, "bend", turning every joint (50 rotation channels, `LINEAR`, one
//! second), as a `.glb` loaded as any file is.

use rastty_scene::model::{Model, NoFiles, load_gltf_bytes};

/// Rings of the tube.
const RINGS: usize = 100;
/// Vertices a ring.
const SEGMENTS: usize = 100;
/// Joints along the tube.
pub const JOINTS: usize = 50;
/// The tube's length and each joint's step along it.
const LENGTH: f32 = 5.0;

/// The tube as a `.glb`.
pub fn tube_glb() -> Vec<u8> {
    let mut bin: Vec<u8> = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    let mut add = |bytes: Vec<u8>, accessor: String| {
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        views.push(format!(r#"{{"buffer": 0, "byteOffset": {}, "byteLength": {}}}"#, bin.len(), bytes.len()));
        bin.extend(bytes);
        accessors.push(accessor.replace("VIEW", &(views.len() - 1).to_string()));
        accessors.len() - 1
    };
    let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let f32_accessor = |count: usize, kind: &str| {
        format!(r#"{{"bufferView": VIEW, "componentType": 5126, "count": {count}, "type": "{kind}"}}"#)
    };
    let (mut positions, mut normals, mut joints, mut weights, mut bulge, mut twist) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let step = LENGTH / JOINTS as f32;
    for r in 0..RINGS {
        let y = LENGTH * r as f32 / (RINGS - 1) as f32;
        let along = (y / step - 0.5).clamp(0.0, (JOINTS - 1) as f32);
        let (j0, t) = (along.floor() as usize, along.fract());
        let j1 = (j0 + 1).min(JOINTS - 1);
        for s in 0..SEGMENTS {
            let a = std::f32::consts::TAU * s as f32 / SEGMENTS as f32;
            let (x, z) = (0.3 * a.cos(), 0.3 * a.sin());
            positions.extend([x, y, z]);
            normals.extend([a.cos(), 0.0, a.sin()]);
            joints.extend([j0 as u16, j1 as u16, 0, 0]);
            weights.extend([1.0 - t, t, 0.0, 0.0]);
            bulge.extend([0.1 * a.cos(), 0.0, 0.1 * a.sin()]);
            twist.extend([-0.05 * a.sin(), 0.0, 0.05 * a.cos()]);
        }
    }
    let mut indices: Vec<u32> = Vec::new();
    for r in 0..RINGS as u32 - 1 {
        for s in 0..SEGMENTS as u32 {
            let (a, b) = (r * SEGMENTS as u32 + s, r * SEGMENTS as u32 + (s + 1) % SEGMENTS as u32);
            let (c, d) = (a + SEGMENTS as u32, b + SEGMENTS as u32);
            indices.extend([a, c, b, b, c, d]);
        }
    }
    let n = RINGS * SEGMENTS;
    let mut bounds = f32_accessor(n, "VEC3");
    bounds.pop();
    let position = add(floats(&positions), bounds + r#", "min": [-0.3, 0, -0.3], "max": [0.3, 5, 0.3]}"#);
    let normal = add(floats(&normals), f32_accessor(n, "VEC3"));
    let joint_bytes = joints.iter().flat_map(|j| j.to_le_bytes()).collect();
    let joint =
        add(joint_bytes, format!(r#"{{"bufferView": VIEW, "componentType": 5123, "count": {n}, "type": "VEC4"}}"#));
    let weight = add(floats(&weights), f32_accessor(n, "VEC4"));
    let bulge = add(floats(&bulge), f32_accessor(n, "VEC3"));
    let twist = add(floats(&twist), f32_accessor(n, "VEC3"));
    let index_bytes = indices.iter().flat_map(|i| i.to_le_bytes()).collect();
    let index = add(
        index_bytes,
        format!(r#"{{"bufferView": VIEW, "componentType": 5125, "count": {}, "type": "SCALAR"}}"#, indices.len()),
    );
    let inverse_binds: Vec<f32> = (0..JOINTS)
        .flat_map(|k| [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -step * k as f32, 0.0, 1.0])
        .collect();
    let ibm = add(floats(&inverse_binds), f32_accessor(JOINTS, "MAT4"));
    let times = add(floats(&[0.0, 1.0]), f32_accessor(2, "SCALAR"));
    let (s, c) = (0.025f32.sin(), 0.025f32.cos());
    let turn = add(floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, s, c]), f32_accessor(2, "VEC4"));
    // Node 0 holds the mesh; nodes 1 to 50 are the chain of joints.
    let mut nodes = vec![format!(r#"{{"mesh": 0, "skin": 0}}"#)];
    for k in 0..JOINTS {
        let children = if k + 1 < JOINTS { format!(r#", "children": [{}]"#, k + 2) } else { String::new() };
        let y = if k == 0 { 0.0 } else { step };
        nodes.push(format!(r#"{{"translation": [0, {y}, 0]{children}}}"#));
    }
    let joint_list: Vec<String> = (1..=JOINTS).map(|k| k.to_string()).collect();
    let channels: Vec<String> =
        (1..=JOINTS).map(|k| format!(r#"{{"sampler": 0, "target": {{"node": {k}, "path": "rotation"}}}}"#)).collect();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "buffers": [{{"byteLength": {len}}}], "bufferViews": [{views}],
        "accessors": [{accessors}], "scene": 0, "scenes": [{{"nodes": [0, 1]}}], "nodes": [{nodes}],
        "skins": [{{"joints": [{joint_list}], "inverseBindMatrices": {ibm}}}],
        "meshes": [{{"weights": [0.3, 0.1], "primitives": [{{"attributes": {{"POSITION": {position},
          "NORMAL": {normal}, "JOINTS_0": {joint}, "WEIGHTS_0": {weight}}}, "indices": {index},
          "targets": [{{"POSITION": {bulge}}}, {{"POSITION": {twist}}}]}}]}}],
        "animations": [{{"name": "bend", "samplers": [{{"input": {times}, "output": {turn}}}],
          "channels": [{channels}]}}]}}"#,
        len = bin.len(),
        views = views.join(", "),
        accessors = accessors.join(", "),
        nodes = nodes.join(", "),
        joint_list = joint_list.join(", "),
        channels = channels.join(", "),
    );
    let mut json = json.into_bytes();
    json.resize(json.len().next_multiple_of(4), b' ');
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = (12 + 8 + json.len() + 8 + bin.len()) as u32;
    let mut out = b"glTF".to_vec();
    for word in [2, total, json.len() as u32] {
        out.extend(word.to_le_bytes());
    }
    out.extend(b"JSON");
    out.extend(&json);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(&bin);
    out
}

/// The tube loaded as a model (checked: 10,000 vertices, one skin of [`JOINTS`] joints).
pub fn tube() -> Model {
    let model = load_gltf_bytes("tube.glb", &tube_glb(), &NoFiles).expect("the tube loads");
    assert_eq!((model.positions.len(), model.rig.as_ref().unwrap().skins().next()), (10_000, Some((None, JOINTS))));
    model
}
