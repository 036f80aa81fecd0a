//! The frame checksum: 32-bit FNV-1a.

/// 32-bit FNV-1a (offset basis `0x811C9DC5`, prime `0x01000193`).
///
/// A frame's checksums are this hash of its RGB565 words, and of its `u16` depths, in frame order (row 0 first,
/// left to right), each word fed as its two little-endian bytes: low byte, then high byte ([`Fnv1a::write_words`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fnv1a(u32);

impl Fnv1a {
    /// The FNV-1a 32-bit offset basis.
    pub const OFFSET_BASIS: u32 = 0x811C_9DC5;
    /// The FNV 32-bit prime.
    pub const PRIME: u32 = 0x0100_0193;

    /// A hash of nothing yet.
    pub const fn new() -> Self {
        Self(Self::OFFSET_BASIS)
    }

    /// Folds in one byte.
    #[inline(always)]
    pub fn write_u8(&mut self, byte: u8) {
        self.0 = (self.0 ^ u32::from(byte)).wrapping_mul(Self::PRIME);
    }

    /// Folds in 16-bit words (RGB565 colours, `u16` depths), each as its little-endian bytes.
    pub fn write_words(&mut self, words: &[u16]) {
        for &word in words {
            let [low, high] = word.to_le_bytes();
            self.write_u8(low);
            self.write_u8(high);
        }
    }

    /// The hash so far.
    pub const fn finish(&self) -> u32 {
        self.0
    }
}

impl Default for Fnv1a {
    fn default() -> Self {
        Self::new()
    }
}
