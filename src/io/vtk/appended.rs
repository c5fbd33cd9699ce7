//! How one data array's bytes are stored in a VTK XML file's raw appended section.
//!
//! Uncompressed: a UInt64 byte count, then the bytes. Compressed (`compressor=
//! "vtkZLibDataCompressor"`): the bytes cut into blocks of [`BLOCK`] bytes, each compressed
//! with zlib on its own, after a header of UInt64 words: the number of blocks, the block size,
//! the size of the last block when it is partial (0 when it is full), then each block's
//! compressed size. That is the layout VTK's own writers produce and its readers expect
//! (`header_type="UInt64"`).

use flate2::write::ZlibEncoder;
use rayon::prelude::*;
use std::io::Write as _;

/// Uncompressed bytes per block, as VTK's writers use: small enough to compress the blocks in
/// parallel, large enough that zlib's per-block overhead stays below 0.1 %.
pub const BLOCK: usize = 1 << 15;

/// zlib level 1: on float fields it compresses about as well as the default level 6 (the
/// entropy is in the low mantissa bits either way) and several times faster.
const LEVEL: u32 = 1;

/// Appends `raw` to `out` uncompressed, after its byte count.
pub fn append_raw(raw: &[u8], out: &mut Vec<u8>) {
    out.extend_from_slice(&(raw.len() as u64).to_le_bytes());
    out.extend_from_slice(raw);
}

/// Appends `raw` to `out` as zlib-compressed blocks after their header (module doc). The
/// blocks are compressed in parallel; each one's bytes depend only on its input, so the file
/// is the same for any number of threads.
pub fn append_zlib(raw: &[u8], out: &mut Vec<u8>) {
    let blocks: Vec<Vec<u8>> = raw
        .par_chunks(BLOCK)
        .map(|chunk| {
            let mut z = ZlibEncoder::new(Vec::new(), flate2::Compression::new(LEVEL));
            // Writing to a Vec cannot fail.
            z.write_all(chunk).expect("compress into memory");
            z.finish().expect("compress into memory")
        })
        .collect();
    let header = [blocks.len(), BLOCK, raw.len() % BLOCK]
        .into_iter()
        .chain(blocks.iter().map(Vec::len));
    for word in header {
        out.extend_from_slice(&(word as u64).to_le_bytes());
    }
    for b in &blocks {
        out.extend_from_slice(b);
    }
}

/// Reads back the array that starts at `data[offset..]`, as a VTK reader does: the inverse of
/// [`append_raw`] or, when `compressed`, of [`append_zlib`]. Panics on a malformed array.
#[cfg(test)]
pub fn read(data: &[u8], offset: usize, compressed: bool) -> Vec<u8> {
    use std::io::Read as _;
    let word = |k: usize| {
        let at = offset + 8 * k;
        u64::from_le_bytes(data[at..at + 8].try_into().unwrap()) as usize
    };
    if !compressed {
        return data[offset + 8..offset + 8 + word(0)].to_vec();
    }
    let (blocks, size, last) = (word(0), word(1), word(2));
    let mut at = offset + 8 * (3 + blocks);
    let mut out = Vec::new();
    for b in 0..blocks {
        let n = word(3 + b);
        let mut block = Vec::new();
        flate2::read::ZlibDecoder::new(&data[at..at + n])
            .read_to_end(&mut block)
            .unwrap();
        let expected = if b + 1 == blocks && last != 0 {
            last
        } else {
            size
        };
        assert_eq!(block.len(), expected, "block {b} of {blocks}");
        out.extend_from_slice(&block);
        at += n;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zlib_blocks_read_back_with_vtk_header() {
        // Empty, one partial block, exactly two full blocks, and two and a bit.
        for len in [0, 1000, 2 * BLOCK, 2 * BLOCK + 17] {
            let raw: Vec<u8> = (0..len).map(|i| (i * 7 % 251) as u8).collect();
            let mut out = vec![0xAB; 5];
            append_zlib(&raw, &mut out);
            let words: Vec<u64> = out[5..5 + 24]
                .chunks_exact(8)
                .map(|c| u64::from_le_bytes(c.try_into().unwrap()))
                .collect();
            let blocks = len.div_ceil(BLOCK) as u64;
            assert_eq!(words, [blocks, BLOCK as u64, (len % BLOCK) as u64]);
            assert_eq!(read(&out, 5, true), raw, "{len} bytes");
            let mut plain = Vec::new();
            append_raw(&raw, &mut plain);
            assert_eq!(read(&plain, 0, false), raw);
        }
    }
}
