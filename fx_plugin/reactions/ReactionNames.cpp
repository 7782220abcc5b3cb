// Spellings of the enum words, shared by the loader (parsing), messages and README examples.
#include "reactions/ReactionDesc.h"

namespace fx {

const char* reactionTypeName(ReactionType type) {
    switch (type) {
    case ReactionType::WheelSmoke: return "wheel_smoke";
    case ReactionType::Dust: return "dust";
    case ReactionType::CollisionBurst: return "collision_burst";
    case ReactionType::CollisionScrape: return "collision_scrape";
    case ReactionType::OnDemand: return "on_demand";
    }
    return "?";
}

const char* wheelSetName(WheelSet wheels) {
    switch (wheels) {
    case WheelSet::Rear: return "rear";
    case WheelSet::Front: return "front";
    case WheelSet::All: return "all";
    }
    return "?";
}

const char* blendModeName(BlendMode blend) {
    switch (blend) {
    case BlendMode::Alpha: return "alpha";
    case BlendMode::Premultiplied: return "premultiplied";
    case BlendMode::Additive: return "additive";
    }
    return "?";
}

const char* techniqueName(Technique technique) {
    switch (technique) {
    case Technique::FromReaction: return "from_reaction";
    case Technique::Hard: return "hard";
    case Technique::Soft: return "soft";
    case Technique::Spherical: return "spherical";
    case Technique::Mega: return "mega";
    }
    return "?";
}

const char* surfaceName(Surface surface) {
    switch (surface) {
    case Surface::Asphalt: return "asphalt";
    case Surface::Kerb: return "kerb";
    case Surface::Grass: return "grass";
    case Surface::Gravel: return "gravel";
    case Surface::Sand: return "sand";
    case Surface::Count: break;
    }
    return "?";
}

}  // namespace fx
