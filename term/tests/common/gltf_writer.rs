//! glTF files written by the tests themselves: a binary buffer of accessors gathered here, and the rest of the
//! JSON (meshes, nodes, materials, ...) given as text, out as `.gltf` (buffer in a data URI or a file beside it)
//! or `.glb`.

use base64::Engine;

/// A glTF file being written: its one buffer, buffer views and accessors.
#[derive(Default)]
pub struct GltfWriter {
    /// The buffer's bytes.
    pub bin: Vec<u8>,
    views: Vec<String>,
    accessors: Vec<String>,
}

impl GltfWriter {
    /// An empty file.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends `bytes` (from a 4-byte boundary) as a buffer view; its index.
    pub fn view(&mut self, bytes: &[u8]) -> usize {
        while self.bin.len() % 4 != 0 {
            self.bin.push(0);
        }
        self.views.push(format!(r#"{{"buffer": 0, "byteOffset": {}, "byteLength": {}}}"#, self.bin.len(), bytes.len()));
        self.bin.extend_from_slice(bytes);
        self.views.len() - 1
    }

    /// An accessor of `values` as floats, `kind` `"SCALAR"`, `"VEC2"`, `"VEC3"` or `"VEC4"`; its index.
    pub fn floats(&mut self, values: &[f32], kind: &str) -> usize {
        let components = match kind {
            "SCALAR" => 1,
            "VEC2" => 2,
            "VEC3" => 3,
            _ => 4,
        };
        let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
        let view = self.view(&bytes);
        let count = values.len() / components;
        let bounds = if kind == "VEC3" {
            let extreme = |f: fn(f32, f32) -> f32, start: f32| -> Vec<f32> {
                (0..3).map(|c| values.iter().skip(c).step_by(3).copied().fold(start, f)).collect()
            };
            format!(r#", "min": {:?}, "max": {:?}"#, extreme(f32::min, f32::MAX), extreme(f32::max, f32::MIN))
        } else {
            String::new()
        };
        self.accessor(&format!(
            r#"{{"bufferView": {view}, "componentType": 5126, "count": {count}, "type": "{kind}"{bounds}}}"#
        ))
    }

    /// An index accessor of `values` stored in `bytes` (1, 2 or 4) bytes each; its index.
    pub fn indices(&mut self, values: &[u32], bytes: usize) -> usize {
        let data: Vec<u8> = values.iter().flat_map(|&v| v.to_le_bytes()[..bytes].to_vec()).collect();
        let view = self.view(&data);
        let component = match bytes {
            1 => 5121,
            2 => 5123,
            _ => 5125,
        };
        self.accessor(&format!(
            r#"{{"bufferView": {view}, "componentType": {component}, "count": {}, "type": "SCALAR"}}"#,
            values.len()
        ))
    }

    /// Adds an accessor written out in full; its index.
    pub fn accessor(&mut self, json: &str) -> usize {
        self.accessors.push(json.to_owned());
        self.accessors.len() - 1
    }

    /// The JSON of the file, its buffer at `uri` (`None` for a `.glb`'s binary chunk), with `rest` (top-level
    /// members, comma-separated, without braces) after the buffers, views and accessors.
    pub fn json(&self, uri: Option<&str>, rest: &str) -> String {
        let uri = uri.map(|u| format!(r#", "uri": "{u}""#)).unwrap_or_default();
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "buffers": [{{"byteLength": {}{uri}}}], "bufferViews": [{}], "accessors": [{}], {rest}}}"#,
            self.bin.len(),
            self.views.join(", "),
            self.accessors.join(", ")
        )
    }

    /// A `.gltf` file with the buffer inside it as a base64 data URI.
    pub fn embedded(&self, rest: &str) -> String {
        let data = base64::engine::general_purpose::STANDARD.encode(&self.bin);
        self.json(Some(&format!("data:application/octet-stream;base64,{data}")), rest)
    }

    /// A `.glb` file: the JSON chunk and the binary chunk.
    pub fn glb(&self, rest: &str) -> Vec<u8> {
        let mut json = self.json(None, rest).into_bytes();
        while json.len() % 4 != 0 {
            json.push(b' ');
        }
        let mut bin = self.bin.clone();
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(json.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&json);
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
        out
    }
}
