//! Reading a glTF accessor's elements from the file's buffers, every offset, stride and count checked against the
//! bytes there are before anything is allocated or read.
//!
//! The `gltf` crate's own reader trusts those numbers (an accessor of count 0, a stride smaller than an element
//! or a type other than the one asked for are assertions or arithmetic overflow there), so a file made to break
//! it could; this reader turns each into an error naming the accessor.

use gltf::Accessor;
use gltf::accessor::sparse::IndexType;
use gltf::accessor::{DataType, Dimensions};
use gltf::buffer::View;

/// The most elements an accessor without a buffer view may have (its elements are zeros, so the file's size does
/// not bound them): 16,777,216.
pub(crate) const MAX_VIEWLESS_ELEMENTS: usize = 1 << 24;

/// The bytes of each buffer of a file, by index.
pub(crate) type Buffers<'a> = [std::borrow::Cow<'a, [u8]>];

/// The elements of an accessor as floats: `components` per element, normalised integers mapped to `[0, 1]` or
/// `[-1, 1]` as the glTF 2.0 specification decodes them (section 3.11: `f = max(c / (2^(b-1) - 1), -1)` signed,
/// `f = c / (2^b - 1)` unsigned), other integers converted to their value.
pub(crate) struct Floats {
    /// Components per element (1 to 4).
    pub components: usize,
    /// `count * components` values.
    pub values: Vec<f32>,
}

impl Floats {
    /// The elements as `[f32; N]`: their first `N` components (an RGBA colour read as RGB drops its alpha).
    pub fn elements<const N: usize>(&self) -> impl Iterator<Item = [f32; N]> + '_ {
        self.values.chunks_exact(self.components.max(1)).map(move |c| {
            let mut out = [0.0; N];
            for (o, v) in out.iter_mut().zip(c) {
                *o = *v;
            }
            out
        })
    }
}

/// Reads `accessor` as floats. `allowed` lists the element sizes (1 to 4 components) the caller accepts.
///
/// # Errors
/// A message naming the accessor when its type is not allowed, it is matrix-typed, or its data does not fit the
/// buffer view or buffer it names.
pub(crate) fn read_floats(accessor: &Accessor<'_>, buffers: &Buffers<'_>, allowed: &[usize]) -> Result<Floats, String> {
    let components = vector_size(accessor)?;
    if !allowed.contains(&components) {
        return Err(format!("accessor {} has {components} components, expected {allowed:?}", accessor.index()));
    }
    let (data_type, normalized) = (accessor.data_type(), accessor.normalized());
    let read = |bytes: &[u8]| -> f32 { component_float(data_type, normalized, bytes) };
    let values = read_elements(accessor, buffers, components, |bytes, out: &mut Vec<f32>| {
        let size = data_type.size();
        out.extend(bytes.chunks_exact(size).take(components).map(read));
    })?;
    if values.iter().any(|v| !v.is_finite()) {
        return Err(format!("accessor {} holds a value that is not finite", accessor.index()));
    }
    Ok(Floats { components, values })
}

/// Reads a `MAT4` accessor of `f32` (a skin's inverse bind matrices), each matrix's 16 values column by column.
///
/// # Errors
/// A message naming the accessor when it is not of `f32` 4x4 matrices, does not fit its buffer, or holds a value
/// that is not finite.
pub(crate) fn read_mat4s(accessor: &Accessor<'_>, buffers: &Buffers<'_>) -> Result<Vec<[f32; 16]>, String> {
    if accessor.dimensions() != Dimensions::Mat4 || accessor.data_type() != DataType::F32 {
        return Err(format!("accessor {} should hold 4x4 matrices of floats", accessor.index()));
    }
    let values = read_elements(accessor, buffers, 16, |bytes, out: &mut Vec<f32>| {
        out.extend(bytes.chunks_exact(4).map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])));
    })?;
    if values.iter().any(|v| !v.is_finite()) {
        return Err(format!("accessor {} holds a value that is not finite", accessor.index()));
    }
    Ok(values.chunks_exact(16).map(|m| core::array::from_fn(|i| m[i])).collect())
}

/// Reads an index accessor: unsigned 8, 16 or 32-bit scalars, exactly.
///
/// # Errors
/// A message naming the accessor when it is not an unsigned scalar or does not fit its buffer.
pub(crate) fn read_indices(accessor: &Accessor<'_>, buffers: &Buffers<'_>) -> Result<Vec<u32>, String> {
    let data_type = accessor.data_type();
    if accessor.dimensions() != Dimensions::Scalar || !matches!(data_type, DataType::U8 | DataType::U16 | DataType::U32)
    {
        return Err(format!("accessor {} holds indices but is not of unsigned integer scalars", accessor.index()));
    }
    read_elements(accessor, buffers, 1, |bytes, out: &mut Vec<u32>| out.push(unsigned(bytes, data_type.size())))
}

/// Components per element of a vector or scalar accessor.
fn vector_size(accessor: &Accessor<'_>) -> Result<usize, String> {
    match accessor.dimensions() {
        Dimensions::Scalar => Ok(1),
        Dimensions::Vec2 => Ok(2),
        Dimensions::Vec3 => Ok(3),
        Dimensions::Vec4 => Ok(4),
        _ => Err(format!("accessor {} is a matrix where a vector was expected", accessor.index())),
    }
}

/// The elements of `accessor` (dense data, then sparse substitutions), each element's bytes handed to `push`.
fn read_elements<T: Default + Clone>(
    accessor: &Accessor<'_>,
    buffers: &Buffers<'_>,
    components: usize,
    push: impl Fn(&[u8], &mut Vec<T>),
) -> Result<Vec<T>, String> {
    let index = accessor.index();
    let count = accessor.count();
    let element = accessor.data_type().size() * components;
    let mut out = Vec::new();
    match accessor.view() {
        Some(view) => {
            let (bytes, stride) = strided(&view, buffers, accessor.offset(), count, element)
                .map_err(|e| format!("accessor {index}: {e}"))?;
            out.reserve_exact(count * components);
            for i in 0..count {
                push(&bytes[i * stride..i * stride + element], &mut out);
            }
        }
        None => {
            if count > MAX_VIEWLESS_ELEMENTS {
                return Err(format!(
                    "accessor {index} has no buffer view and {count} elements, more than the {MAX_VIEWLESS_ELEMENTS} \
                     read"
                ));
            }
            out.resize(count * components, T::default());
        }
    }
    if let Some(sparse) = accessor.sparse() {
        let n = sparse.count();
        let indices = sparse.indices();
        let index_size = match indices.index_type() {
            IndexType::U8 => 1,
            IndexType::U16 => 2,
            IndexType::U32 => 4,
        };
        let (places, place_stride) = strided(&indices.view(), buffers, indices.offset(), n, index_size)
            .map_err(|e| format!("accessor {index}'s sparse indices: {e}"))?;
        let (values, value_stride) = strided(&sparse.values().view(), buffers, sparse.values().offset(), n, element)
            .map_err(|e| format!("accessor {index}'s sparse values: {e}"))?;
        let mut one = Vec::with_capacity(components);
        for i in 0..n {
            let place = unsigned(&places[i * place_stride..], index_size) as usize;
            if place >= count {
                return Err(format!("accessor {index}: sparse index {place} is beyond its {count} elements"));
            }
            one.clear();
            push(&values[i * value_stride..i * value_stride + element], &mut one);
            out[place * components..(place + 1) * components].clone_from_slice(&one);
        }
    }
    Ok(out)
}

/// The bytes of `view` from `offset` that hold `count` elements of `element` bytes, and the view's stride between
/// them; checked to lie within the view, and the view within its buffer.
fn strided<'b>(
    view: &View<'_>,
    buffers: &'b Buffers<'_>,
    offset: usize,
    count: usize,
    element: usize,
) -> Result<(&'b [u8], usize), String> {
    let buffer = buffers.get(view.buffer().index()).ok_or("its buffer is missing")?;
    let view_end = view.offset().checked_add(view.length()).filter(|end| *end <= buffer.len()).ok_or_else(|| {
        format!(
            "buffer view {} ({} bytes from byte {}) reaches beyond its buffer's {} bytes",
            view.index(),
            view.length(),
            view.offset(),
            buffer.len()
        )
    })?;
    let bytes = &buffer[view.offset()..view_end];
    let stride = view.stride().unwrap_or(element);
    if stride < element {
        return Err(format!(
            "buffer view {}'s stride of {stride} bytes is less than an element's {element}",
            view.index()
        ));
    }
    if count == 0 {
        return Err("it has no elements (a count of 0)".into());
    }
    let end = (count - 1)
        .checked_mul(stride)
        .and_then(|n| n.checked_add(element))
        .and_then(|n| n.checked_add(offset))
        .filter(|end| *end <= bytes.len())
        .ok_or_else(|| {
            format!(
                "{count} elements of {element} bytes from byte {offset} do not fit buffer view {}'s {} bytes",
                view.index(),
                bytes.len()
            )
        })?;
    Ok((&bytes[offset..end], stride))
}

/// A little-endian unsigned integer of `size` (1, 2 or 4) bytes from the start of `bytes`.
fn unsigned(bytes: &[u8], size: usize) -> u32 {
    match size {
        1 => u32::from(bytes[0]),
        2 => u32::from(u16::from_le_bytes([bytes[0], bytes[1]])),
        _ => u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
    }
}

/// One component as a float (the glTF 2.0 specification, section 3.11: normalised integers).
fn component_float(data_type: DataType, normalized: bool, bytes: &[u8]) -> f32 {
    let (value, max): (f32, f32) = match data_type {
        DataType::I8 => (f32::from(bytes[0] as i8), 127.0),
        DataType::U8 => (f32::from(bytes[0]), 255.0),
        DataType::I16 => (f32::from(i16::from_le_bytes([bytes[0], bytes[1]])), 32767.0),
        DataType::U16 => (f32::from(u16::from_le_bytes([bytes[0], bytes[1]])), 65535.0),
        DataType::U32 => (u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]) as f32, 4_294_967_295.0),
        DataType::F32 => return f32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
    };
    if normalized { (value / max).max(-1.0) } else { value }
}
