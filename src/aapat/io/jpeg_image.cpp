#include "aapat/io/jpeg_image.h"

#include <fmt/format.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

#include <jpeglib.h>

#include "aapat/io/png_image.h"

namespace aapat {
namespace {

// libjpeg reports a fatal error through error_exit, which must not return:
// it jumps back to the decoder with the library's message kept.
struct ErrorJump {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
  auto* e = reinterpret_cast<ErrorJump*>(info->err);
  (*info->err->format_message)(info, e->message);
  std::longjmp(e->jump, 1);
}

void on_warning(j_common_ptr, int) {}  // corrupt-data warnings: the decoded image stands

// The decoding itself, with no C++ object alive across setjmp: fills `rgb`
// (sized by the caller after the header) or returns libjpeg's message.
struct Decoded {
  unsigned width = 0, height = 0;
  bool too_large = false;
  std::string error;
};

}  // namespace

bool is_jpeg(std::string_view b) {
  return b.size() >= 3 && static_cast<unsigned char>(b[0]) == 0xFF &&
         static_cast<unsigned char>(b[1]) == 0xD8 && static_cast<unsigned char>(b[2]) == 0xFF;
}

ColorImage decode_jpeg(std::string_view bytes, const std::string& path, const std::string& what,
                       const ImageLimits& limits) {
  if (!is_jpeg(bytes)) throw Error(fmt::format("{} '{}': not a JPEG image", what, path));
  jpeg_decompress_struct info{};
  ErrorJump err{};
  info.err = jpeg_std_error(&err.base);
  err.base.error_exit = on_error;
  err.base.emit_message = on_warning;
  std::vector<unsigned char> pixels;  // constructed before setjmp, resized only after the header
  Decoded d;
  if (setjmp(err.jump)) {
    jpeg_destroy_decompress(&info);
    throw Error(fmt::format("{} '{}': cannot decode the JPEG ({})", what, path, err.message));
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()),
               static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  d.width = info.image_width;
  d.height = info.image_height;
  if (d.width < 1 || d.height < 1 || d.width > limits.max_side || d.height > limits.max_side ||
      size_t{d.width} * d.height > limits.max_pixels) {
    jpeg_destroy_decompress(&info);
    throw Error(
        fmt::format("{} '{}': {}x{} pixels; at most {} per side and {} in all "
                    "(docs/limits.md)",
                    what, path, d.width, d.height, limits.max_side, limits.max_pixels));
  }
  info.out_color_space = JCS_RGB;  // grey and YCbCr files alike
  pixels.resize(size_t{3} * d.width * d.height);
  jpeg_start_decompress(&info);
  while (info.output_scanline < info.output_height) {
    unsigned char* row = &pixels[size_t{3} * d.width * info.output_scanline];
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  ColorImage out{static_cast<int>(d.width), static_cast<int>(d.height),
                 std::vector<float>(pixels.size())};
  for (size_t k = 0; k < pixels.size(); ++k) out.rgb[k] = pixels[k] / 255.0f;
  return out;
}

}  // namespace aapat
