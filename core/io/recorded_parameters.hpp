#pragma once
// The parameters a model base recorded it was built with (its parameters text,
// core/io/parameters_text.hpp), read back into their structs: what every analysis of a scene
// recognized against the base must use, so live scans are analysed exactly as the model
// views were.
#include <filesystem>
#include <string>

#include "core/cosmos_parameters.hpp"
#include "core/input_error.hpp"
#include "core/io/parameters_text.hpp"
#include "core/modelbase/model_base.hpp"

namespace cosmos {

// The parameters under `prefix` ("cosmos", "conditioning", ...) of `base`. InputError naming
// `file` and the first key the base lacks (a base older than that parameter: rebuild it).
template <class Parameters>
Parameters recorded_parameters(const ModelBase& base, const std::filesystem::path& file,
                               const std::string& prefix) {
  const auto values = ParameterValues::parse(base.parameters_text);
  if (!values) throw InputError(file.string() + ": its parameters text is not a JSON object");
  Parameters parameters;
  if (const auto missing = read_parameter_values(*values, prefix, parameters))
    throw InputError(file.string() + ": built without " + *missing +
                     " (a base older than that parameter): rebuild it");
  return parameters;
}

// The COSMOS parameters the base was built with (its cosmos.* keys).
inline CosmosParameters model_base_cosmos_parameters(const ModelBase& base,
                                                     const std::filesystem::path& file) {
  return recorded_parameters<CosmosParameters>(base, file, "cosmos");
}

}  // namespace cosmos
