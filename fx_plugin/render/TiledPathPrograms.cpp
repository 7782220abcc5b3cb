#include "TiledPath.h"

#include <utility>

#include "render/PrivateGl.h"

namespace fx {

// The tiled programs of the cache and their uniforms' locations (TiledPath.h).
void TiledPath::bind(const ProgramCache& programs) {
    software_ = softwareRasterizer(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    sort_.bind(programs);
    setup_ = programs.passProgram(ProgramCache::TiledSetup);
    shade_ = programs.passProgram(ProgramCache::TiledShade);
    composite_ = programs.passProgram(ProgramCache::TiledComposite);
    setupLit_ = programs.passProgram(ProgramCache::TiledSetupLit);
    shadeLit_ = programs.passProgram(ProgramCache::TiledShadeLit);
    // Each program's uniforms (-1 where it has none of that name: glUniform ignores those).
    const std::pair<ShadeUniforms*, uint32_t> located[4] = {
        {&setupUniforms_, setup_}, {&shadeUniforms_, shade_}, {&setupLitUniforms_, setupLit_}, {&shadeLitUniforms_, shadeLit_}};
    for (const auto& program : located) {
        ShadeUniforms* u = program.first;
        const uint32_t prog = program.second;
        *u = ShadeUniforms{};
        if (!prog) continue;
        u->view = glGetUniformLocation(prog, "uView");
        u->proj = glGetUniformLocation(prog, "uProj");
        u->nearPlane = glGetUniformLocation(prog, "uNear");
        u->farPlane = glGetUniformLocation(prog, "uFar");
        u->atlas = glGetUniformLocation(prog, "uAtlas");
        u->ramp = glGetUniformLocation(prog, "uRamp");
        u->sceneDepth = glGetUniformLocation(prog, "uSceneDepth");
        u->batchA = glGetUniformLocation(prog, "uBatchA");
        u->batchB = glGetUniformLocation(prog, "uBatchB");
        u->batchRange = glGetUniformLocation(prog, "uBatchRange");
        u->batchCount = glGetUniformLocation(prog, "uBatchCount");
        u->instanceCount = glGetUniformLocation(prog, "uInstanceCount");
        u->pixelSlope = glGetUniformLocation(prog, "uPixelSlope");
        u->tileCount = glGetUniformLocation(prog, "uTileCount");
        u->groupsX = glGetUniformLocation(prog, "uGroupsX");
        u->viewSize = glGetUniformLocation(prog, "uViewSize");
        u->pixelToNdc = glGetUniformLocation(prog, "uPixelToNdc");
        u->atlasTexels = glGetUniformLocation(prog, "uAtlasTexels");
        u->decode.locate(prog);
        u->fog = FogUniforms::of(prog);
        u->batchLight = glGetUniformLocation(prog, "uBatchLight");
        u->batchShade = glGetUniformLocation(prog, "uBatchShade");
        u->sunView = glGetUniformLocation(prog, "uSunView");
        u->sunColor = glGetUniformLocation(prog, "uSunColor");
        u->shadowed = glGetUniformLocation(prog, "uShadowed");
        u->viewToShadow = glGetUniformLocation(prog, "uViewToShadow");
        u->opacity = glGetUniformLocation(prog, "uOpacity");
        u->litAtlas = glGetUniformLocation(prog, "uLitAtlas");
        u->trimmed = glGetUniformLocation(prog, "uTrimmed");
        u->shapeBuckets = glGetUniformLocation(prog, "uShapeBuckets");
        u->lodScale = glGetUniformLocation(prog, "uLodScale");
    }
    if (composite_) {
        compositeAccum_ = glGetUniformLocation(composite_, "uAccum");
        compositeOrigin_ = glGetUniformLocation(composite_, "uDrawOrigin");
        compositeViewSize_ = glGetUniformLocation(composite_, "uViewSize");
    }
}

}  // namespace fx
