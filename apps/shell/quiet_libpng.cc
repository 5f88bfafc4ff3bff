#include "apps/shell/quiet_libpng.h"

#include <dlfcn.h>
#include <png.h>

#include <atomic>

namespace novelty::apps {
namespace {

std::atomic<int>& Silenced() {
  static std::atomic<int> count{0};
  return count;
}

// libpng's png_error calls the handler and, if it returns, its default one, which prints: the
// handler must leave by png_longjmp as the default does after printing.
[[noreturn]] void SilentError(png_structp png, png_const_charp) {
  ++Silenced();
  png_longjmp(png, 1);
}

void SilentWarning(png_structp, png_const_charp) {
  ++Silenced();
}

template <typename F>
F Real(const char* symbol) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, symbol));  // libpng's own, after this library
}

}  // namespace

void QuietLibpng() {}

int SilencedLibpngMessages() {
  return Silenced().load();
}

}  // namespace novelty::apps

extern "C" {

// A caller's own handlers are kept; only the missing ones are filled in.
png_structp png_create_read_struct(png_const_charp version, png_voidp error_ptr,
                                   png_error_ptr error_fn, png_error_ptr warn_fn) {
  using Create = png_structp (*)(png_const_charp, png_voidp, png_error_ptr, png_error_ptr);
  static const Create real = novelty::apps::Real<Create>("png_create_read_struct");
  return real(version, error_ptr, error_fn ? error_fn : novelty::apps::SilentError,
              warn_fn ? warn_fn : novelty::apps::SilentWarning);
}

png_structp png_create_write_struct(png_const_charp version, png_voidp error_ptr,
                                    png_error_ptr error_fn, png_error_ptr warn_fn) {
  using Create = png_structp (*)(png_const_charp, png_voidp, png_error_ptr, png_error_ptr);
  static const Create real = novelty::apps::Real<Create>("png_create_write_struct");
  return real(version, error_ptr, error_fn ? error_fn : novelty::apps::SilentError,
              warn_fn ? warn_fn : novelty::apps::SilentWarning);
}

}  // extern "C"
