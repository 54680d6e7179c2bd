#include "sim/source/simulated_source.hpp"

namespace cosmos {

SimulatedSource::SimulatedSource(const PartCatalog& catalog, const ScannerParameters& parameters,
                                 const SimulatedSourceSettings& settings,
                                 const FaultInjectionSettings& faults)
    : parameters_(parameters),
      conveyor_(catalog, parameters, settings),
      scanner_(std::make_unique<SimulatedScanner>(conveyor_.scene(), parameters, settings.mode)),
      faults_(faults, parameters.encoder_ticks_per_profile) {}

SimulatedSource::SimulatedSource(const std::vector<SimPartModel>& models,
                                 const ScannerParameters& parameters,
                                 const SimulatedSourceSettings& settings,
                                 const FaultInjectionSettings& faults)
    : parameters_(parameters),
      conveyor_(models, parameters, settings),
      scanner_(std::make_unique<SimulatedScanner>(conveyor_.scene(), parameters, settings.mode)),
      faults_(faults, parameters.encoder_ticks_per_profile) {}

SimulatedSource::~SimulatedSource() = default;

SourceStatus SimulatedSource::start() {
  next_profile_ = 0;
  faults_.restart();
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
  for (; next_profile_ <= conveyor_.last_profile(); ++next_profile_) {
    const SourceFaultInjector::Action action = faults_.before(next_profile_);
    if (action == SourceFaultInjector::Action::kLose) continue;
    if (action == SourceFaultInjector::Action::kTimeout) {
      ++next_profile_;
      error_.set("simulated source: profile %lld: no frame (injected camera stall)",
                 static_cast<long long>(next_profile_ - 1));
      return SourceStatus::kTimeout;
    }
    scanner_->acquire(next_profile_, out);
    faults_.after(next_profile_, out);
    out.seq = static_cast<std::uint64_t>(next_profile_);
    ++next_profile_;
    return SourceStatus::kOk;
  }
  return SourceStatus::kEndOfStream;
}

}  // namespace cosmos
