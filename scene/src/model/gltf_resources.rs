//! The data a glTF file's buffers and images name: the binary chunk of a `.glb`, `data:` URIs inside the file,
//! and files beside it (read through a [`Resolver`], under the rule every model's referenced files follow).

use std::borrow::Cow;
use std::path::PathBuf;

use base64::Engine;
use gltf::buffer;

use super::gltf_accessor::Buffers;
use super::resolver::Resolver;
use super::texture_image::TextureImage;

/// The bytes of every buffer of `document`, by index: each at least as long as it says it is.
///
/// # Errors
/// A message naming the buffer when its data is missing, cannot be read or decoded, or is shorter than its
/// `byteLength`.
pub(crate) fn load_buffers<'a>(
    document: &gltf::Document,
    blob: Option<&'a [u8]>,
    files: &'a dyn Resolver,
) -> Result<Vec<Cow<'a, [u8]>>, String> {
    let mut buffers: Vec<Cow<'a, [u8]>> = Vec::new();
    for buffer in document.buffers() {
        let index = buffer.index();
        let data: Cow<'a, [u8]> = match buffer.source() {
            buffer::Source::Bin => {
                Cow::Borrowed(blob.ok_or_else(|| format!("buffer {index} is the binary chunk, which the file lacks"))?)
            }
            buffer::Source::Uri(uri) => uri_data(uri, files).map_err(|e| format!("buffer {index}: {e}"))?,
        };
        if data.len() < buffer.length() {
            return Err(format!("buffer {index} declares {} bytes but its data holds {}", buffer.length(), data.len()));
        }
        buffers.push(data);
    }
    Ok(buffers)
}

/// Decodes image `index` of `document` (PNG or JPEG) from its buffer view, `data:` URI or file.
///
/// The image is read from the JSON, not through `gltf::Image::source`, which (in 1.4.1) panics on an image with a
/// buffer view but no MIME type, or with neither a buffer view nor a URI.
///
/// # Errors
/// A message naming the image when its data cannot be had or decoded.
pub(crate) fn load_image(
    document: &gltf::Document,
    index: usize,
    buffers: &Buffers<'_>,
    files: &dyn Resolver,
) -> Result<TextureImage, String> {
    let image = document.as_json().images.get(index).ok_or_else(|| format!("image {index} does not exist"))?;
    let (name, bytes): (PathBuf, Cow<'_, [u8]>) = match (&image.buffer_view, &image.uri) {
        (Some(view), _) => {
            let view =
                document.views().nth(view.value()).ok_or_else(|| format!("image {index}: no such buffer view"))?;
            let buffer =
                buffers.get(view.buffer().index()).ok_or_else(|| format!("image {index}: its buffer is missing"))?;
            let range = view.offset()..view.offset().saturating_add(view.length());
            let bytes = buffer.get(range).ok_or_else(|| {
                format!(
                    "image {index}: buffer view {} reaches beyond its buffer's {} bytes",
                    view.index(),
                    buffer.len()
                )
            })?;
            (PathBuf::from(format!("image {index}")), Cow::Borrowed(bytes))
        }
        (None, Some(uri)) => {
            let name = if uri.starts_with("data:") { format!("image {index}") } else { percent_decoded(uri)? };
            (PathBuf::from(name), uri_data(uri, files).map_err(|e| format!("image {index}: {e}"))?)
        }
        (None, None) => return Err(format!("image {index} has neither a buffer view nor a URI")),
    };
    TextureImage::decode(&name, &bytes).map_err(|e| e.to_string())
}

/// The bytes a URI names: a `data:` URI's base64 payload, or a file relative to the model's folder.
fn uri_data<'a>(uri: &str, files: &'a dyn Resolver) -> Result<Cow<'a, [u8]>, String> {
    if let Some(data) = uri.strip_prefix("data:") {
        let Some((_, payload)) = data.split_once(";base64,") else {
            return Err("a data: URI that is not base64".into());
        };
        return base64::engine::general_purpose::STANDARD
            .decode(payload)
            .map(Cow::Owned)
            .map_err(|e| format!("bad base64 in a data: URI ({e})"));
    }
    if uri.contains("://") {
        return Err(format!("{}: only files beside the model and data: URIs are read", crate::escaped::Escaped(uri)));
    }
    let path = PathBuf::from(percent_decoded(uri)?);
    files.read(&path).map_err(|e| format!("{}: {e}", files.describe(&path).display()))
}

/// A relative URI reference with its `%XX` escapes decoded (RFC 3986, section 2.1).
fn percent_decoded(uri: &str) -> Result<String, String> {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = bytes.get(i + 1..i + 3).and_then(|h| std::str::from_utf8(h).ok());
            let value = hex.and_then(|h| u8::from_str_radix(h, 16).ok());
            let Some(value) = value else { return Err(format!("a bad %-escape in the URI {uri:?}")) };
            out.push(value);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| format!("the URI {uri:?} is not UTF-8 once decoded"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Embedded;

    #[test]
    fn uris_are_decoded_from_base64_or_read_as_files() {
        let files: &[(&str, &[u8])] = &[("my tex.bin", b"FILE")];
        let files = Embedded::new(files);
        assert_eq!(&*uri_data("data:application/octet-stream;base64,AAEC", &files).unwrap(), &[0, 1, 2]);
        assert_eq!(&*uri_data("my%20tex.bin", &files).unwrap(), b"FILE");
        assert!(uri_data("data:text/plain,hello", &files).unwrap_err().contains("not base64"));
        assert!(uri_data("https://example.com/a.bin", &files).unwrap_err().contains("only files beside"));
        assert!(uri_data("a%2", &files).unwrap_err().contains("bad %-escape"));
    }
}
