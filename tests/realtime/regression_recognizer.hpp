#pragma once
// What the simulated-cell tests share: the regression model base, its catalog and a recognizer
// over it, loaded once per test suite (SetUpTestSuite / TearDownTestSuite).
#include <filesystem>
#include <memory>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "sim/part_catalog.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos::testing {

struct RegressionRecognizer {
  RegressionRecognizer()
      : base(read_model_base(regression_model_base())),
        catalog(read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) /
                                  "config/parts-regression.yaml")),
        recognizer(base, CosmosParameters{}, RecognitionParameters{}) {}

  ModelBase base;
  PartCatalog catalog;
  Recognizer recognizer;  // reads `base`, declared after it
};

}  // namespace cosmos::testing
