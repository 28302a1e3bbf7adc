// archgeo — the table of problem builders (`problem:` in a spec).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "problems/builder.h"

namespace archgeo {

// The names accepted by `problem:`, in the order the docs list them.
std::vector<std::string> BuilderNames();

// A builder with default settings; nullptr for an unknown name.
std::unique_ptr<Builder> MakeBuilder(const std::string& name);

// One factory per builder (defined next to each builder).
std::unique_ptr<Builder> MakePlanarQuadsBuilder();
std::unique_ptr<Builder> MakeHNetBuilder();
std::unique_ptr<Builder> MakeTotalAbsoluteCurvatureBuilder();
std::unique_ptr<Builder> MakeSmoothMeshBuilder();
std::unique_ptr<Builder> MakePrincipalSymmetricBuilder();

}  // namespace archgeo
