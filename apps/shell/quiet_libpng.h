// libpng prints "libpng error: …" and "libpng warning: …" on stderr itself when the library that
// calls it (OpenCV's PNG codec, through cv::imread and MRPT's CImage) gives it no handlers; the
// caller then fails with a message of its own, so the user read two or three lines for one bad
// file. This library defines png_create_read_struct and png_create_write_struct, which the
// dynamic loader finds before libpng's (a program's direct dependencies come first), and passes
// handlers that say nothing: an error still ends the decoding as libpng's own handler does
// (png_longjmp), so cv::imread returns an empty image and the program names the file.
#pragma once

namespace novelty::apps {

/// Makes sure the silent handlers are linked into the program; RunProgram calls it.
void QuietLibpng();

/// How many libpng errors and warnings were silenced so far (for tests).
int SilencedLibpngMessages();

}  // namespace novelty::apps
