#pragma once
// docs/parameters.md: every parameter of the cell with its default, description and range,
// generated from the parameter structs' visit() lists (core/parameter_visitor.hpp), never
// written by hand. `cosmos config docs` prints it; a test fails when the committed file
// differs from it.
#include <string>

namespace cosmos {

std::string parameters_markdown();

}  // namespace cosmos
