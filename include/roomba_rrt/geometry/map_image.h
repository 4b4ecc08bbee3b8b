// A map's image decoded to the bytes map_server reads: netpbm (PBM, PGM, PPM; ASCII or raw) read
// here, PNG through libpng, each to what SDL2_image (map_server's decoder) gives map_server.
// Libraries made for images alone: a node that reads a map does not load SDL2's window, audio and
// input stack (X11, Wayland, PulseAudio, ALSA, ...) to decode it.
//
// The bytes per pixel are SDL2_image's surface's:
//   - PGM, grey PNG: one byte, the grey level (a PGM's scaled to 0..255 from its maxval; a PNG's
//     of 1, 2 or 4 bits expanded to 0..255, of 16 bits cut to 8);
//   - PBM, palette PNG: one byte, the index (PBM: 1 is black), as map_server reads an 8-bit
//     surface's bytes, not its palette's colours;
//   - PPM, RGB PNG: three bytes, R G B;
//   - RGBA PNG, grey + alpha PNG (as grey grey grey alpha), a palette or grey PNG with
//     transparency beyond one fully transparent index: four bytes, R G B A.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace roomba_rrt::geometry {

/// A decoded image: `height` rows of `width` pixels, top row first, `channels` bytes a pixel.
struct MapImage {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<std::uint8_t> pixels;
};

/// Decodes the PNM or PNG image at `path`. Throws util::InvalidInput (field "image") naming the
/// file for anything it cannot decode: another format, a header without a width and height, no
/// pixels or more than `max_pixels` (from the header, before any pixel is allocated), a
/// truncated file, a PNM whose maxval is above 255 (SDL2_image reads 8-bit PNMs only).
MapImage decodeMapImage(const std::string& path,
                        long long max_pixels = std::numeric_limits<long long>::max());

}  // namespace roomba_rrt::geometry
