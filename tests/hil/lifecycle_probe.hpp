#pragma once
// The camera's lifecycle and format negotiation against vivid's capture node:
//   lifecycle  open → set_format → allocate_buffers → stream_on → dequeue/requeue frames →
//              stream_off → release_buffers → close, twice in one process, and a restart of
//              the stream without closing: the process's file descriptors and the node's
//              mappings are back to what they were, and the second run gets the buffers again
//              (a leaked buffer queue would leave the node busy);
//   formats    what the node enumerates, each of the camera's pixel formats taken unchanged,
//              and what the driver cannot give refused with one line naming device and
//              format: a frame wider than the input, a ROI below its last row.
#include <vector>

#include "firmware_bridge/camera_config.hpp"
#include "tests/hil/check_line.hpp"

namespace cosmos::hil {

std::vector<ProbeCheck> probe_lifecycle(const CameraConfig& camera);
std::vector<ProbeCheck> probe_formats(const CameraConfig& camera);

}  // namespace cosmos::hil
