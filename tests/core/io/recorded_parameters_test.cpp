// The parameters a model base recorded, read back (core/io/recorded_parameters.hpp): every
// COSMOS field, changed from its default, comes back as written; a base lacking a key is
// refused naming the file and the key.
#include "core/io/recorded_parameters.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tests/common/parameter_fields.hpp"

namespace cosmos {
namespace {

TEST(RecordedParameters, TheCosmosParametersReadBackFromTheBase) {
  CosmosParameters written;
  testing::FieldChanger changer(testing::FieldChanger::kAll);
  visit_parameters(changer, written);
  ParameterText text;
  text.set_parameters("cosmos", written);
  ModelBase base;
  base.parameters_text = text.text();
  const CosmosParameters read = model_base_cosmos_parameters(base, "base.cmb");
  EXPECT_EQ(testing::parameter_leaves(read), testing::parameter_leaves(written));
  EXPECT_EQ(read.smoothing.iterations, 17);

  ModelBase older;
  older.parameters_text = "{\"cosmos\": {\"fit\": {\"window_size\": 5}}}";
  try {
    model_base_cosmos_parameters(older, "old.cmb");
    FAIL() << "a base without every COSMOS parameter was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "old.cmb: built without cosmos.fit.bicubic (a base older than that parameter): "
              "rebuild it");
  }
}

}  // namespace
}  // namespace cosmos
