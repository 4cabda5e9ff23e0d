// What the animation and analysis views play: a source kind by name, a shipped name or file,
// and a viewer script for the kinds that need one. The kinds themselves are the window's
// source-kind table (session/player/animation_sources.h). Plain C++.
#pragma once

#include <string>

namespace oflab {

// A choice of source: a kind of the table, a shipped name or file (the script or the
// scene; empty for the scene panel's plane) and, for kinds that need one, a viewer script.
struct SourceChoice {
  std::string kind = "plane";
  std::string name;
  std::string viewer;
  bool operator==(const SourceChoice& o) const {
    return kind == o.kind && name == o.name && viewer == o.viewer;
  }
};

}  // namespace oflab
