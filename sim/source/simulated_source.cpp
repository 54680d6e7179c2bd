#include "sim/source/simulated_source.hpp"

namespace cosmos {

SimulatedSource::SimulatedSource(const PartCatalog& catalog, const ScannerParameters& parameters,
                                 const SimulatedSourceSettings& settings)
    : parameters_(parameters),
      conveyor_(catalog, parameters, settings),
      scanner_(std::make_unique<SimulatedScanner>(conveyor_.scene(), parameters, settings.mode)) {}

SimulatedSource::SimulatedSource(const std::vector<SimPartModel>& models,
                                 const ScannerParameters& parameters,
                                 const SimulatedSourceSettings& settings)
    : parameters_(parameters),
      conveyor_(models, parameters, settings),
      scanner_(std::make_unique<SimulatedScanner>(conveyor_.scene(), parameters, settings.mode)) {}

SimulatedSource::~SimulatedSource() = default;

SourceStatus SimulatedSource::start() {
  next_profile_ = 0;
  started_ = true;
  error_.clear();
  return SourceStatus::kOk;
}

void SimulatedSource::reserve(Profile& profile) const { scanner_->reserve(profile); }

SourceStatus SimulatedSource::next(Profile& out) noexcept {
  if (!started_) {
    error_.set("simulated source: next() before start()");
    return SourceStatus::kError;
  }
  if (next_profile_ > conveyor_.last_profile()) return SourceStatus::kEndOfStream;
  scanner_->acquire(next_profile_, out);
  out.seq = static_cast<std::uint64_t>(next_profile_);
  ++next_profile_;
  return SourceStatus::kOk;
}

}  // namespace cosmos
