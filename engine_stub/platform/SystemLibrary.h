#pragma once
// A platform back end's system library (libOSMesa, libEGL, libglfw), opened at run time with
// dlopen instead of linked. A program then starts with only the back end it uses installed:
// `--backend egl` on a GPU machine does not need Mesa's software renderer (libOSMesa pulls in
// llvmpipe and LLVM, about 100 MB), and a missing library is an error that names the package
// to install, not a loader failure before main().
//
// The back ends keep their system headers for types and constants only; every entry point is
// resolved through resolve() into a table of function pointers.
#include <string>

namespace cube {

/// Which library a back end opens and what to tell the user when it cannot.
/// Defaults: none; every field must be set (string literals, they are kept by pointer).
struct SystemLibraryDesc {
    const char* backend = nullptr;      ///< the --backend value named in messages: "osmesa"
    const char* soname = nullptr;       ///< what dlopen asks for: "libOSMesa.so.8"
    const char* overrideEnv = nullptr;  ///< a variable naming another path or soname to open
                                        ///< instead (tests point it at a missing file)
    const char* install = nullptr;      ///< the advice: "Debian's libosmesa6"
};

/// An opened library. It is never closed: llvmpipe's worker threads and Mesa's and GLFW's
/// exit handlers outlive the contexts made through it, and unloading code under them crashes.
/// Opening the same library again (a second Platform) only takes another reference.
class SystemLibrary {
public:
    /// Opens desc.soname, or $desc.overrideEnv when that is set and not empty. A name holding a
    /// '/' is a path and must be a regular file (a FIFO or a folder is refused, named, without
    /// blocking); a plain soname goes through the system search. On failure returns false with
    /// e.g. "--backend osmesa: cannot load libOSMesa.so.8 (<dlerror>); install Debian's
    /// libosmesa6".
    bool open(const SystemLibraryDesc& desc, std::string* error);

    /// Looks up `name` into *fn (a function pointer). On failure returns false with a message
    /// naming the symbol, the library, the backend flag and the package. Call after open().
    template <class Fn>
    bool resolve(const char* name, Fn* fn, std::string* error) const {
        void* address = symbol(name, error);
        if (!address) return false;
        *fn = reinterpret_cast<Fn>(address);
        return true;
    }

    /// The path or soname actually opened (the override when one was set).
    const std::string& name() const { return name_; }

private:
    void* symbol(const char* name, std::string* error) const;

    SystemLibraryDesc desc_;
    std::string name_;
    bool overridden_ = false;
    void* handle_ = nullptr;
};

/// Opens `desc`'s library and fills the function table `api` from it (a struct declared with
/// CUBE_SYSTEM_LIBRARY_TABLE). False with the message of the first failure; `api` may then be
/// partly filled.
template <class Api>
bool loadSystemLibrary(const SystemLibraryDesc& desc, Api* api, std::string* error) {
    SystemLibrary lib;
    return lib.open(desc, error) && api->resolveAll(lib, error);
}

}  // namespace cube

/// The body of a back end's function table: for each entry point of the X-macro `LIST`, a
/// pointer of the system header's type named like the function (null until resolved), and
/// resolveAll(lib, error), which looks each one up by its own name in order and stops at the
/// first that is missing.
#define CUBE_SYSTEM_LIBRARY_TABLE(LIST)                                          \
    LIST(CUBE_SYSTEM_LIBRARY_DECLARE_)                                           \
    bool resolveAll(const ::cube::SystemLibrary& lib, std::string* error) {      \
        return true LIST(CUBE_SYSTEM_LIBRARY_RESOLVE_);                          \
    }
#define CUBE_SYSTEM_LIBRARY_DECLARE_(name) decltype(&::name) name = nullptr;
#define CUBE_SYSTEM_LIBRARY_RESOLVE_(name) &&lib.resolve(#name, &name, error)
