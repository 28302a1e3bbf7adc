// archgeo — where builders send their progress lines (one per iteration).
#pragma once

#include <functional>
#include <string>

namespace archgeo {

using ProgressSink = std::function<void(const std::string& line)>;

}  // namespace archgeo
