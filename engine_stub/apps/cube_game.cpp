#include <cstdio>
#include "platform/Platform.h"
#include "gl/Gl.h"
int main() {
    std::string err;
    cube::PlatformDesc d;
    auto p = cube::Platform::create(d, &err);
    if (!p) { std::fprintf(stderr, "%s\n", err.c_str()); return 1; }
    std::printf("%s soft=%d\n", p->rendererName().c_str(), int(p->softwareRenderer()));
    return 0;
}
