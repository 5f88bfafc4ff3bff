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

using Create = png_structp (*)(png_const_charp, png_voidp, png_error_ptr, png_error_ptr);

// libpng's own `symbol` (the next definition after this library's) called with the silent
// handlers where the caller gave none; a caller's own handlers are kept.
png_structp CreateQuietly(const char* symbol, png_const_charp version, png_voidp error_ptr,
                          png_error_ptr error_fn, png_error_ptr warn_fn) {
  const auto real = reinterpret_cast<Create>(dlsym(RTLD_NEXT, symbol));
  if (!real) return nullptr;  // as libpng says it cannot make one; callers check
  return real(version, error_ptr, error_fn ? error_fn : SilentError,
              warn_fn ? warn_fn : SilentWarning);
}

}  // namespace

void QuietLibpng() {}

int SilencedLibpngMessages() {
  return Silenced().load();
}

}  // namespace novelty::apps

extern "C" {

png_structp png_create_read_struct(png_const_charp version, png_voidp error_ptr,
                                   png_error_ptr error_fn, png_error_ptr warn_fn) {
  return novelty::apps::CreateQuietly("png_create_read_struct", version, error_ptr, error_fn,
                                      warn_fn);
}

png_structp png_create_write_struct(png_const_charp version, png_voidp error_ptr,
                                    png_error_ptr error_fn, png_error_ptr warn_fn) {
  return novelty::apps::CreateQuietly("png_create_write_struct", version, error_ptr, error_fn,
                                      warn_fn);
}

}  // extern "C"
