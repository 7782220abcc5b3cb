#pragma once
// The technique vocabulary of reaction files in one table: a row per `render.technique` word.
// The loader (ReactionSchema.cpp), the editor schema and reactionValue (ReactionKeyTable.cpp),
// techniqueName() and the plugin's reaction stats all read it; tests/panel/EditSessionTest.cpp
// walks every row from a file through the loader, the schema, reactionValue and a saved file.
// Adding a technique is adding a row here (and the renderer that draws it).
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Plugin.h"  // Technique

namespace fx {

/// Which of the plugin's renderers draws a technique (render/Renderers.h owns one of each).
enum class DrawnBy : uint8_t {
    Billboards,  ///< ParticleRenderer: camera-facing cards from the CPU pools
    Mega,        ///< MegaRenderer: blurred spheres melted into one volume
    Stateless,   ///< StatelessRenderer: birth records evaluated in the vertex shader
};

struct TechniqueRow {
    const char* word;          ///< spelling in a reaction file: `render.technique: soft`
    Technique technique;       ///< how it is drawn (stateless particles are hard billboards)
    bool stateless;            ///< birth records evaluated in the vertex shader, no CPU update
    bool needsSceneDepth;      ///< its fragments read the scene depth (fade, sphere depth)
    bool raySphere;            ///< a fragment is a ray through a sphere (box footprint at quarter res)
    const char* displayName;   ///< what menus, help and tables call it
    DrawnBy drawnBy;           ///< the renderer that draws it (and prepares its programs)
    bool powerPrograms;        ///< a program per contrast_power, built ahead for each loaded one
};

/// Every technique, in the order the loader's messages list them (never changes).
const std::vector<TechniqueRow>& techniqueTable();
/// The row spelled `word` in a file, or null.
const TechniqueRow* findTechnique(const std::string& word);
/// The row a loaded reaction's render settings came from (`stateless` wins over `technique`);
/// `technique` is one of Hard, Soft, Spherical, Mega (asserted).
const TechniqueRow& techniqueRow(Technique technique, bool stateless);
/// The row a reaction is drawn with under `override` (FromReaction: the reaction's own; a
/// stateless reaction keeps its own row whatever the override, as its storage is another).
const TechniqueRow& drawnRow(Technique reactionTechnique, bool stateless, Technique override);
/// techniqueBit mask (1 << Technique) of the techniques `renderer` draws.
uint32_t techniquesDrawnBy(DrawnBy renderer);
/// The file words, table order.
std::vector<std::string> techniqueWords();

}  // namespace fx
