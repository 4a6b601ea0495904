#include "frob/render/image.hpp"

#include "frob/render/output_file.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace frob::render {

namespace {

// libpng reports errors by longjmp; keeping it in its own frame keeps that away from C++ locals.
bool writePngStream(std::FILE* f, const Image& image) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, f);
  // Speed over size: frames are many and short-lived.
  png_set_compression_level(png, 1);
  png_set_filter(png, 0, PNG_FILTER_NONE);
  // Frames are opaque: store RGB, a quarter less to compress; libpng skips each fourth byte.
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4);
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

Status writePng(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    return Status::failure("png: cannot write '" + path + "': the image is empty or its size does not match its pixels");
  }
  if (Status s = checkWritable(path, "png"); !s) return s;
  const std::string tmp = partialPath(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) return Status::failure("png: cannot write '" + path + "': " + std::strerror(errno));
  bool ok = writePngStream(f, image);
  if (std::fclose(f) != 0) ok = false;
  if (!ok) {
    discardPartial(path);
    return Status::failure("png: writing '" + path + "' failed (disk full?)");
  }
  return commitPartial(path, "png");
}

Result<Image> readPng(const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, path.c_str()) == 0) {
    return Status::failure("png: cannot read '" + path + "': " + png.message);
  }
  png.format = PNG_FORMAT_RGBA;
  Image image{.width = static_cast<int>(png.width), .height = static_cast<int>(png.height), .rgba = {}};
  image.rgba.resize(PNG_IMAGE_SIZE(png));
  if (png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr) == 0) {
    const std::string msg = png.message;
    png_image_free(&png);
    return Status::failure("png: cannot decode '" + path + "': " + msg);
  }
  return image;
}

Status validateOutputDirectory(const std::string& dir) { return checkWritable((std::filesystem::path(dir) / "frame_000000.png").string(), "frames"); }

std::string framePath(const std::string& dir, long index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06ld.png", index);
  return (std::filesystem::path(dir) / name).string();
}

}  // namespace frob::render
