#pragma once
// The JSON form of a recognition result, the stable contract of `cosmos recognize --json`:
// {status, reason, part, view, score, spectral_distance, registration_rms_mm, inlier_fraction,
//  rotation: [[3x3]], translation_mm: [x, y, z], timings_ms: {features, selection, matching,
//  registration, total}, candidates: [{part, view, spectral_distance, goodness, rms_mm}]}.
// `part` is the part's name (null when rejected), `view` its view-sphere index.
#include <nlohmann/json.hpp>

#include "core/modelbase/model_base.hpp"
#include "core/recognition/recognizer.hpp"

namespace cosmos {

nlohmann::ordered_json recognition_json(const RecognitionResult& result, const ModelBase& base);

}  // namespace cosmos
