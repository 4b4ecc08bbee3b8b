#include "roomba_rrt/geometry/map_image.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::geometry {
namespace {

using util::InvalidInput;

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw InvalidInput("image", "cannot decode '" + path + "': " + why);
}

/// Refuses an image of `width` × `height` pixels without pixels or with more than `max_pixels`,
/// from its header, before any pixel is allocated.
void checkSize(const std::string& path, long long width, long long height, long long max_pixels) {
  if (width < 1 || height < 1) {
    throw InvalidInput("image", "'" + path + "' has no pixels (" + std::to_string(width) + " x " +
                                    std::to_string(height) + ")");
  }
  if (width > max_pixels || height > max_pixels || width * height > max_pixels) {
    throw InvalidInput("image", "'" + path + "' has " + std::to_string(width) + " x " +
                                    std::to_string(height) + " pixels; at most " +
                                    std::to_string(max_pixels) + " cells are supported");
  }
}

/// A netpbm file: the header's numbers (whitespace and '#' comments skipped) read from the file,
/// then, once its size is known to be supported, the rest of it in one read and its pixels.
class PnmReader {
 public:
  PnmReader(const std::string& path, std::ifstream& in) : path_(path), in_(in) {}

  MapImage read(long long max_pixels) {
    const int p = get(), digit = get() - '0';
    if (p != 'P' || digit < 1 || digit > 6) {
      throw InvalidInput("image", "'" + path_ + "' is not a PGM or PNG image");
    }
    const bool ascii = digit <= 3;
    const int kind = (digit - 1) % 3;  // 0 PBM, 1 PGM, 2 PPM
    const std::optional<long long> width = number(), height = number();
    if (!width || !height) {
      throw InvalidInput("image", "'" + path_ + "': a PNM header without its width and height");
    }
    checkSize(path_, *width, *height, max_pixels);
    const std::optional<long long> maxval = kind == 0 ? 1 : number();
    if (!maxval) refuse(path_, "a header without its maxval");
    if (*maxval <= 0 || *maxval > 255) refuse(path_, "only 8-bit netpbm images are read");
    readRest();
    MapImage image;
    image.width = static_cast<int>(*width);
    image.height = static_cast<int>(*height);
    image.channels = kind == 2 ? 3 : 1;
    const int scale = static_cast<int>(*maxval);
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * image.channels;
    image.pixels.resize(row_bytes * image.height);
    for (int y = 0; y < image.height; ++y) {
      std::uint8_t* row = image.pixels.data() + row_bytes * y;
      if (ascii) {
        for (std::size_t i = 0; i < row_bytes; ++i) row[i] = kind == 0 ? bit() : value();
      } else if (kind == 0) {  // raw PBM: 8 pixels a byte, the first in the high bit
        const std::size_t packed = (static_cast<std::size_t>(image.width) + 7) / 8;
        if (at_ + packed > rest_.size()) refuse(path_, "truncated");
        for (int i = 0; i < image.width; ++i) {
          row[i] = (static_cast<unsigned char>(rest_[at_ + i / 8]) >> (7 - i % 8)) & 1;
        }
        at_ += packed;
      } else {
        if (at_ + row_bytes > rest_.size()) refuse(path_, "truncated");
        std::copy_n(rest_.begin() + static_cast<std::ptrdiff_t>(at_), row_bytes, row);
        at_ += row_bytes;
      }
      if (kind != 0 && scale < 255) {  // to the full range, as SDL2_image does
        for (std::size_t i = 0; i < row_bytes; ++i) row[i] = row[i] * 255 / scale;
      }
    }
    return image;
  }

 private:
  /// The next byte: from the file while the header is read, then from the rest read at once.
  int get() {
    if (!loaded_) return in_.get();
    return at_ < rest_.size() ? static_cast<unsigned char>(rest_[at_++]) : EOF;
  }
  /// What follows the header, in one read (byte by byte cost 2 ns per pixel).
  void readRest() {
    const std::streamoff from = in_.tellg();
    in_.seekg(0, std::ios::end);
    const std::streamoff end = in_.tellg();
    if (from < 0 || end < from) throw InvalidInput("image", "cannot read '" + path_ + "'");
    rest_.resize(static_cast<std::size_t>(end - from));
    in_.seekg(from);
    if (!in_.read(rest_.data(), end - from)) {
      throw InvalidInput("image", "cannot read '" + path_ + "'");
    }
    loaded_ = true;
  }

  /// A header number: whitespace and comments before it, one character after it; none when the
  /// next thing is not a number.
  std::optional<long long> number() {
    int c = get();
    while (c != EOF && (std::isspace(c) || c == '#')) {
      if (c == '#') {
        while (c != EOF && c != '\n') c = get();
      }
      c = get();
    }
    if (c == EOF || !std::isdigit(c)) return std::nullopt;
    long long value = 0;
    while (c != EOF && std::isdigit(c) && value < (1LL << 40)) {
      value = value * 10 + (c - '0');
      c = get();
    }
    return value;
  }
  /// An ASCII pixel value.
  std::uint8_t value() {
    const std::optional<long long> v = number();
    if (!v) refuse(path_, "truncated");
    return static_cast<std::uint8_t>(*v);
  }
  /// An ASCII PBM pixel: the next '0' or '1', anything else skipped.
  std::uint8_t bit() {
    for (int c = get(); c != EOF; c = get()) {
      if (c == '0' || c == '1') return static_cast<std::uint8_t>(c - '0');
    }
    refuse(path_, "truncated");
  }

  std::string path_;
  std::ifstream& in_;
  bool loaded_ = false;
  std::vector<char> rest_;
  std::size_t at_ = 0;
};

/// libpng's errors end in a longjmp back into decodePng, which turns them into InvalidInput.
struct PngError {
  std::jmp_buf jump;
  char message[256] = "";
};

void onPngError(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(error->message, sizeof error->message, "%s", message);
  std::longjmp(error->jump, 1);
}
void onPngWarning(png_structp, png_const_charp) {}

/// What decodePng fills in, on the heap: nothing that changes after setjmp() lives in a local
/// variable (whose value a longjmp() would leave indeterminate).
struct PngRead {
  PngError error;
  png_structp png = nullptr;
  png_infop info = nullptr;
  MapImage image;
  std::vector<png_bytep> rows;
  ~PngRead() { png_destroy_read_struct(&png, &info, nullptr); }
};

MapImage decodePng(const std::string& path, std::FILE* file, long long max_pixels) {
  const auto read = std::make_unique<PngRead>();
  read->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &read->error, onPngError, onPngWarning);
  if (read->png) read->info = png_create_info_struct(read->png);
  if (!read->info) refuse(path, "out of memory");
  if (setjmp(read->error.jump)) refuse(path, read->error.message);
  png_structp png = read->png;
  png_infop info = read->info;
  png_init_io(png, file);
  png_set_user_limits(png, 0x7fffffff, 0x7fffffff);  // our limit, checkSize(), says what is wrong
  png_read_info(png, info);
  checkSize(path, png_get_image_width(png, info), png_get_image_height(png, info), max_pixels);
  // The transformations SDL2_image asks of libpng, so that the bytes are its surface's.
  const int color_type = png_get_color_type(png, info);
  png_set_strip_16(png);
  png_set_interlace_handling(png);
  png_set_packing(png);
  if (color_type == PNG_COLOR_TYPE_GRAY) png_set_expand(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS) && color_type == PNG_COLOR_TYPE_PALETTE) {
    // One fully transparent index and the rest opaque: a colour key (the bytes stay indices);
    // any other transparency: RGBA.
    png_bytep alpha = nullptr;
    int count = 0;
    png_get_tRNS(png, info, &alpha, &count, nullptr);
    int transparent = 0;
    bool keyed = true;
    for (int i = 0; i < count && keyed; ++i) {
      if (alpha[i] == 0) {
        keyed = ++transparent <= 1;
      } else if (alpha[i] != 255) {
        keyed = false;
      }
    }
    if (!keyed) png_set_expand(png);
  }
  if (color_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
  png_read_update_info(png, info);
  MapImage& image = read->image;
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  image.channels = png_get_channels(png, info);
  const std::size_t row_bytes = png_get_rowbytes(png, info);
  if (row_bytes != static_cast<std::size_t>(image.width) * image.channels) {
    refuse(path, "an unexpected pixel layout");
  }
  image.pixels.resize(row_bytes * image.height);
  read->rows.resize(image.height);
  for (int y = 0; y < image.height; ++y) read->rows[y] = image.pixels.data() + row_bytes * y;
  png_read_image(png, read->rows.data());
  png_read_end(png, nullptr);
  return std::move(image);
}

}  // namespace

MapImage decodeMapImage(const std::string& path, long long max_pixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput("image", "cannot open '" + path + "'");
  char magic[8] = {};
  in.read(magic, sizeof magic);
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (in.gcount() == 8 && std::equal(kPng, kPng + 8, reinterpret_cast<unsigned char*>(magic))) {
    in.close();
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                               std::fclose);
    if (!file) throw InvalidInput("image", "cannot open '" + path + "'");
    return decodePng(path, file.get(), max_pixels);
  }
  in.clear();
  in.seekg(0);
  return PnmReader(path, in).read(max_pixels);
}

}  // namespace roomba_rrt::geometry
