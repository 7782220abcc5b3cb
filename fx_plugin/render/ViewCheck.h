#pragma once
// The one check of a host's view, shared by both ways in (Plugin::declarePasses and the immediate
// path, which declares through the same renderers) so they refuse the same views alike.
#include <string>

#include "fx/Types.h"

namespace fx {

/// What is wrong with `view` ("" when it is valid; see ViewInfo).
std::string viewProblem(const ViewInfo& view);

}  // namespace fx
