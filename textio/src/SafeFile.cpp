#include "textio/SafeFile.h"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace textio {

const char* fileKindName(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISLNK(mode)) return "a symbolic link";
    return "not a regular file";
}

std::string openErrorText(int err) {
    switch (err) {
        case ENOENT: return "no such file";
        case ELOOP: return "symlink loop (too many levels of symbolic links)";
        case EACCES: return "permission denied";
        case ENOTDIR: return "a folder in the path is not a folder";
        case ENAMETOOLONG: return "path too long";
        default: return std::strerror(err);
    }
}

namespace {

// One reader for both byte containers.
template <class Bytes>
bool readBounded(const std::string& path, size_t maxBytes, Bytes* out, FileError* code, std::string* why) {
    auto fail = [&](FileError c, const std::string& w) {
        if (code) *code = c;
        if (why) *why = w;
        return false;
    };
    if (path.empty()) return fail(FileError::NotFound, "empty path");
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return fail(FileError::NotFound, openErrorText(errno));
    struct FdCloser {
        int fd;
        ~FdCloser() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) return fail(FileError::ReadFailed, openErrorText(errno));
    if (!S_ISREG(st.st_mode)) {
        return fail(FileError::NotRegular,
                    std::string("not a regular file (") + fileKindName(st.st_mode) + ")");
    }
    if (st.st_size < 0 || static_cast<unsigned long long>(st.st_size) > maxBytes) {
        return fail(FileError::TooLarge, std::to_string(static_cast<long long>(st.st_size)) +
                                             " bytes, expected at most " +
                                             std::to_string(maxBytes));
    }
    Bytes data;
    try {
        data.resize(static_cast<size_t>(st.st_size));
    } catch (...) {
        return fail(FileError::TooLarge, "out of memory for " +
                                             std::to_string(static_cast<long long>(st.st_size)) +
                                             " bytes");
    }
    size_t got = 0;
    for (;;) {
        if (got == data.size()) {
            // The file may have grown since fstat: read one byte more to notice.
            if (data.size() > maxBytes) break;
            char probe;
            const ssize_t n = ::read(fd, &probe, 1);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) return fail(FileError::ReadFailed, openErrorText(errno));
            if (n == 0) break;
            data.push_back(static_cast<typename Bytes::value_type>(probe));
            ++got;
            continue;
        }
        const ssize_t n = ::read(fd, reinterpret_cast<char*>(&data[0]) + got, data.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return fail(FileError::ReadFailed, openErrorText(errno));
        if (n == 0) {
            data.resize(got);  // shrank while being read
            break;
        }
        got += static_cast<size_t>(n);
    }
    if (data.size() > maxBytes) {
        return fail(FileError::TooLarge,
                    "grew past " + std::to_string(maxBytes) + " bytes while being read");
    }
    *out = std::move(data);
    if (code) *code = FileError::None;
    return true;
}

}  // namespace

bool readFileBounded(const std::string& path, size_t maxBytes, std::string* out, FileError* code, std::string* why) {
    return readBounded(path, maxBytes, out, code, why);
}

bool readFileBounded(const std::string& path, size_t maxBytes, std::vector<unsigned char>* out, FileError* code,
                     std::string* why) {
    return readBounded(path, maxBytes, out, code, why);
}

std::string describeUnreadable(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return openErrorText(errno);
    if (!S_ISREG(st.st_mode)) return std::string("not a regular file (") + fileKindName(st.st_mode) + ")";
    return "";
}

}  // namespace textio
