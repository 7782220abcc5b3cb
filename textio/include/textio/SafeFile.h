#pragma once
// SafeFile: the one way every loader (reaction files, legacy smoke data, glTF scenes and their
// buffers/images, shaders) reads a file, in the engine and in the plugin alike (both link
// cube_textio; see textio/CMakeLists.txt).
//
// Contract of readFileBounded:
//  - never blocks on a FIFO, socket or device: the file is opened O_NONBLOCK and checked with
//    fstat on the *opened* descriptor (no check-then-open race) before a byte is read;
//  - only regular files are read; anything else is NotRegular with its kind named
//    ("a FIFO", "a directory", ...); a symlink loop is NotFound with "symlink loop";
//  - never reads more than `maxBytes` (+1 to notice a file that grew while being read);
//  - never throws; `why` is a short phrase without the path ("not a regular file (a FIFO)").
#include <cstddef>
#include <string>
#include <vector>

#include <sys/types.h>

namespace textio {

enum class FileError {
    None = 0,
    NotFound,    ///< missing, unreadable (permissions), or a symlink loop
    NotRegular,  ///< a directory, FIFO, socket or device
    TooLarge,    ///< more than maxBytes
    ReadFailed,  ///< an I/O error while reading
};

/// "a FIFO", "a directory", ... for a st_mode that is not a regular file.
const char* fileKindName(mode_t mode);

/// Why open(2) failed, in words a user can act on.
std::string openErrorText(int err);

/// Reads the whole regular file at `path` into `out` (replaced only on success).
/// On failure returns false and sets `*code` and `*why` (either may be null).
bool readFileBounded(const std::string& path, size_t maxBytes, std::string* out, FileError* code, std::string* why);
bool readFileBounded(const std::string& path, size_t maxBytes, std::vector<unsigned char>* out, FileError* code,
                     std::string* why);

/// Why `path` is not a regular file that can be opened ("" when it is one). For listings that
/// must report an entry instead of skipping it. Never blocks (stat only).
std::string describeUnreadable(const std::string& path);

}  // namespace textio
