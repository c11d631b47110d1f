#include "aapat/io/gif_animation.h"

#include <fmt/format.h>
#include <gif_lib.h>

#include <cstring>
#include <memory>

#include "aapat/core/geometry.h"
#include "aapat/io/atomic_file.h"

namespace aapat {
namespace {

[[noreturn]] void gif_fail(const char* what, int code) {
  throw Error(fmt::format("GIF: {} failed: {}", what, GifErrorString(code)));
}

int append(GifFileType* gif, const GifByteType* data, int n) {
  static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(data), n);
  return n;
}

struct Reader {
  const std::string* bytes;
  size_t at = 0;
};

int consume(GifFileType* gif, GifByteType* data, int n) {
  auto* r = static_cast<Reader*>(gif->UserData);
  const size_t k = std::min(static_cast<size_t>(n), r->bytes->size() - r->at);
  std::memcpy(data, r->bytes->data() + r->at, k);
  r->at += k;
  return static_cast<int>(k);
}

}  // namespace

std::string gif_bytes(const GreyFrames& f) {
  if (f.width < 1 || f.height < 1 || f.width > 65535 || f.height > 65535 || f.frames.empty())
    throw Error(fmt::format("GIF: {} frames of {}x{}", f.frames.size(), f.width, f.height));
  std::string out;
  int err = 0;
  GifFileType* gif = EGifOpen(&out, append, &err);
  if (!gif) gif_fail("open", err);
  auto close = [&] {
    if (gif && EGifCloseFile(gif, &err) == GIF_ERROR) gif_fail("close", err);
    gif = nullptr;
  };
  try {
    GifColorType grey[256];
    for (int i = 0; i < 256; ++i)
      grey[i] = {static_cast<GifByteType>(i), static_cast<GifByteType>(i),
                 static_cast<GifByteType>(i)};
    std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> map(GifMakeMapObject(256, grey),
                                                                   GifFreeMapObject);
    EGifSetGifVersion(gif, true);
    if (EGifPutScreenDesc(gif, f.width, f.height, 8, 0, map.get()) == GIF_ERROR)
      gif_fail("screen", gif->Error);
    // NETSCAPE2.0 application block: loop forever.
    const GifByteType app[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    const GifByteType loop[] = {1, 0, 0};
    if (EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(gif, sizeof app, app) == GIF_ERROR ||
        EGifPutExtensionBlock(gif, sizeof loop, loop) == GIF_ERROR ||
        EGifPutExtensionTrailer(gif) == GIF_ERROR)
      gif_fail("loop extension", gif->Error);
    for (const auto& frame : f.frames) {
      if (frame.size() != static_cast<size_t>(f.width) * f.height)
        throw Error("GIF: a frame of the wrong size");
      GraphicsControlBlock gcb{DISPOSE_DO_NOT, false, f.delay_cs, NO_TRANSPARENT_COLOR};
      GifByteType ext[4];
      EGifGCBToExtension(&gcb, ext);
      if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, 4, ext) == GIF_ERROR ||
          EGifPutImageDesc(gif, 0, 0, f.width, f.height, false, nullptr) == GIF_ERROR)
        gif_fail("frame", gif->Error);
      for (int j = 0; j < f.height; ++j)
        if (EGifPutLine(gif, const_cast<GifPixelType*>(&frame[static_cast<size_t>(j) * f.width]),
                        f.width) == GIF_ERROR)
          gif_fail("line", gif->Error);
    }
    close();
  } catch (...) {
    if (gif) EGifCloseFile(gif, &err);
    throw;
  }
  return out;
}

GreyFrames frames_from_gif(const std::string& bytes) {
  Reader r{&bytes};
  int err = 0;
  GifFileType* gif = DGifOpen(&r, consume, &err);
  if (!gif) gif_fail("open", err);
  GreyFrames f;
  const bool ok = DGifSlurp(gif) == GIF_OK;
  if (ok) {
    f.width = gif->SWidth;
    f.height = gif->SHeight;
    for (int k = 0; k < gif->ImageCount; ++k) {
      const SavedImage& im = gif->SavedImages[k];
      const ColorMapObject* map = gif->SColorMap;
      std::vector<uint8_t> px(static_cast<size_t>(f.width) * f.height);
      for (size_t i = 0; i < px.size(); ++i) px[i] = map->Colors[im.RasterBits[i]].Red;
      f.frames.push_back(std::move(px));
    }
  }
  const int code = gif->Error;
  DGifCloseFile(gif, &err);
  if (!ok) gif_fail("read", code);
  return f;
}

void write_gif(const std::string& path, const GreyFrames& frames) {
  write_file_atomically(path, gif_bytes(frames));
}

}  // namespace aapat
