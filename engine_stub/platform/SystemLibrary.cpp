#include "platform/SystemLibrary.h"

#include <cassert>
#include <cstdlib>

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "textio/SafeFile.h"

namespace cube {
namespace {

// "" when `path` is a regular file or cannot be opened at all (dlopen then says why, as for
// any missing library); else what it is ("not a regular file (a FIFO)"). Never blocks: opened
// O_NONBLOCK, checked with fstat on the opened descriptor, no byte read.
std::string notRegularFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return "";
    struct stat st {};
    const bool statted = ::fstat(fd, &st) == 0;
    ::close(fd);
    if (!statted || S_ISREG(st.st_mode)) return "";
    return std::string("not a regular file (") + textio::fileKindName(st.st_mode) + ")";
}

}  // namespace

bool SystemLibrary::open(const SystemLibraryDesc& desc, std::string* error) {
    assert(desc.backend && desc.soname && desc.overrideEnv && desc.install);
    desc_ = desc;
    const char* fromEnv = std::getenv(desc.overrideEnv);
    overridden_ = fromEnv && *fromEnv;
    name_ = overridden_ ? fromEnv : desc.soname;
    // A name with a '/' is a path, and dlopen would open it with a blocking read: a FIFO there
    // hangs start-up until a writer comes, a folder gives a loader message that names no rule.
    // So a path is checked as every other input is (SafeFile's rule: opened non-blocking, fstat
    // on the opened descriptor, regular files only) before the loader sees it. A plain soname
    // goes through the system search, which only ever opens files in library folders.
    if (name_.find('/') != std::string::npos) {
        const std::string why = notRegularFile(name_);
        if (!why.empty()) {
            *error = std::string("--backend ") + desc.backend + ": cannot load " + name_;
            if (overridden_) *error += std::string(", named by ") + desc.overrideEnv;
            *error += " (" + why + "); expected a regular file (a shared library) or a plain library name; install " +
                      desc.install;
            if (overridden_) *error += std::string(" or unset ") + desc.overrideEnv;
            return false;
        }
    }
    // RTLD_NOW: a library too old for an entry point we ask for fails here or in resolve(), not
    // halfway through a frame. RTLD_LOCAL: its symbols stay out of the global namespace, so
    // glad's and the plugin's GL loaders only ever see what a getProcAddress hands them.
    handle_ = dlopen(name_.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_) return true;
    const char* why = dlerror();
    *error = std::string("--backend ") + desc.backend + ": cannot load " + name_;
    if (overridden_) *error += std::string(", named by ") + desc.overrideEnv;
    *error += std::string(" (") + (why ? why : "dlopen failed") + "); install " + desc.install;
    if (overridden_) *error += std::string(" or unset ") + desc.overrideEnv;
    return false;
}

void* SystemLibrary::symbol(const char* name, std::string* error) const {
    assert(handle_ && "SystemLibrary::resolve before a successful open");
    dlerror();  // clear a stale message so the one below belongs to this lookup
    void* address = dlsym(handle_, name);
    if (address) return address;
    const char* why = dlerror();
    *error = std::string("--backend ") + desc_.backend + ": " + name_;
    if (overridden_) *error += std::string(", named by ") + desc_.overrideEnv + ",";
    *error += std::string(" has no ") + name + " (" + (why ? why : "null symbol") +
              "); install or update " + desc_.install;
    if (overridden_) *error += std::string(" or unset ") + desc_.overrideEnv;
    return nullptr;
}

}  // namespace cube
