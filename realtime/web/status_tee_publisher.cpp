#include "realtime/web/status_tee_publisher.hpp"

namespace cosmos {

bool StatusTeePublisher::publish(const CellStatus& status) {
  const bool sent = next_.publish(status);
  store_.update_status(status);
  return sent;
}

}  // namespace cosmos
