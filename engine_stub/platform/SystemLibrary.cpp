#include "platform/SystemLibrary.h"

#include <cassert>
#include <cstdlib>

#include <dlfcn.h>

namespace cube {

bool SystemLibrary::open(const SystemLibraryDesc& desc, std::string* error) {
    assert(desc.backend && desc.soname && desc.overrideEnv && desc.install);
    desc_ = desc;
    const char* fromEnv = std::getenv(desc.overrideEnv);
    overridden_ = fromEnv && *fromEnv;
    name_ = overridden_ ? fromEnv : desc.soname;
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
