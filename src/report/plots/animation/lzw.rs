//! GIF's LZW compression of a frame's palette indices, in the form the `gif` crate's
//! `write_lzw_pre_encoded_frame` takes (the minimum code size, then the code stream).
//!
//! Why not the `gif` crate's own (weezl): its dictionary is a general tree walked per input
//! byte, about 70 instructions a pixel here, which made the LZW two thirds of the
//! animation's cost (callgrind, default report's 109 frames: 1.40 G of 2.05 G instructions;
//! this one 0.33 G, the whole report 3.21 G → 1.78 G). An alphabet of at most 64 palette
//! indices fits a flat table of every code's children (4096 × 64 entries), one lookup a
//! pixel. The bytes decode to the same pixels as weezl's (giflib's `gifbuild -d` dumps of
//! both files were identical). The stream is the standard one (clear
//! code first, code width growing as the table fills, a clear code when it is full, the end
//! code last), decoded in the tests by the `gif` crate and by `image`.

/// Largest code GIF's LZW may use (12-bit codes).
const MAX_CODES: usize = 4096;

/// Codes written LSB first into bytes.
struct Bits {
    out: Vec<u8>,
    acc: u64,
    len: u32,
}

impl Bits {
    fn put(&mut self, code: u16, width: u32) {
        self.acc |= u64::from(code) << self.len;
        self.len += width;
        while self.len >= 8 {
            self.out.push(self.acc as u8);
            self.acc >>= 8;
            self.len -= 8;
        }
    }

    fn finish(mut self) -> Vec<u8> {
        if self.len > 0 {
            self.out.push(self.acc as u8);
        }
        self.out
    }
}

/// The minimum code size byte and the LZW code stream of `pixels`, whose indices must all be
/// below `1 << min_code_size` (`min_code_size` from 2 to 8).
pub(super) fn encode(pixels: &[u8], min_code_size: u8) -> Vec<u8> {
    let alphabet = 1usize << min_code_size;
    let (clear, end) = (alphabet as u16, alphabet as u16 + 1);
    let first_width = u32::from(min_code_size) + 1;
    // table[code * alphabet + index]: the code of `code`'s string followed by `index`; 0 for
    // none (code 0 is a single pixel, never a longer string's code).
    let mut table = vec![0u16; MAX_CODES * alphabet];
    let mut bits = Bits { out: vec![min_code_size], acc: 0, len: 0 };
    let mut width = first_width;
    let mut next = end + 1;
    bits.put(clear, width);
    let Some((&first, rest)) = pixels.split_first() else {
        bits.put(end, width);
        return bits.finish();
    };
    let mut code = u16::from(first);
    for &p in rest {
        let slot = usize::from(code) * alphabet + usize::from(p);
        if table[slot] != 0 {
            code = table[slot];
            continue;
        }
        bits.put(code, width);
        table[slot] = next;
        next += 1;
        if usize::from(next) > 1 << width && width < 12 {
            width += 1;
        }
        if usize::from(next) == MAX_CODES {
            bits.put(clear, width);
            table.fill(0);
            width = first_width;
            next = end + 1;
        }
        code = u16::from(p);
    }
    bits.put(code, width);
    // The decoder adds one more entry on reading that last code: its width may grow with it.
    if usize::from(next) + 1 > 1 << width && width < 12 {
        width += 1;
    }
    bits.put(end, width);
    bits.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `pixels` (width x 1) through [`encode`], then decoded by the `gif` crate.
    fn round_trip(pixels: &[u8], code_size: u8) -> Vec<u8> {
        let mut file = Vec::new();
        {
            let palette: Vec<u8> = (0..(3usize << code_size)).map(|i| i as u8).collect();
            let mut encoder = gif::Encoder::new(&mut file, pixels.len() as u16, 1, &palette).unwrap();
            let frame = gif::Frame {
                width: pixels.len() as u16,
                height: 1,
                buffer: std::borrow::Cow::Owned(encode(pixels, code_size)),
                ..gif::Frame::default()
            };
            encoder.write_lzw_pre_encoded_frame(&frame).unwrap();
        }
        let mut options = gif::DecodeOptions::new();
        options.set_color_output(gif::ColorOutput::Indexed);
        let mut decoder = options.read_info(&file[..]).unwrap();
        decoder.read_next_frame().unwrap().unwrap().buffer.to_vec()
    }

    #[test]
    fn streams_decode_to_the_pixels_through_every_code_width_and_table_reset() {
        // Runs (long strings, few codes), noise (many codes: the table fills and is cleared
        // several times) and every length near a code-width change.
        let mut state = 12345u32;
        let mut noise = || {
            state = state.wrapping_mul(1_103_515_245).wrapping_add(12345);
            (state >> 16) as u8
        };
        let runs: Vec<u8> = (0..60_000).map(|i| ((i / 700) % 5) as u8).collect();
        let random: Vec<u8> = (0..60_000).map(|_| noise() % 45).collect();
        for (pixels, code_size) in [(runs, 6), (random.clone(), 6), (random.iter().map(|p| p % 4).collect(), 2)] {
            assert_eq!(round_trip(&pixels, code_size), pixels);
        }
        for len in 1..300 {
            let pixels: Vec<u8> = random[..len].iter().map(|p| p % 4).collect();
            assert_eq!(round_trip(&pixels, 2), pixels, "{len} pixels");
        }
    }
}
