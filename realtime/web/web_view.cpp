#include "realtime/web/web_view.hpp"

namespace cosmos {

WebView::WebView(const WebViewSettings& settings, const HttpAddress& address,
                 const std::string& what)
    : settings_(settings), address_(address), store_(settings), server_(store_) {
  server_.start(address_, what);
}

std::string WebView::url() const {
  return "http://" + address_.host + ":" + std::to_string(server_.port()) + "/";
}

void WebView::set_belt(double grid_mm, int belt_columns, double x0_loop_mm) {
  store_.set_geometry(
      {.grid_mm = grid_mm,
       .belt_columns = belt_columns,
       .x0_loop_mm = x0_loop_mm,
       .decimation = BeltStripGeometry::decimation_for(settings_.strip_mm_per_pixel, grid_mm)});
}

void WebView::show_state(const std::string& state_text) {
  CellStatus status;
  status.state = CellState::kIdle;
  status.state_text = state_text;
  store_.update_status(status);
}

Publisher& WebView::publisher(Publisher& next) {
  tee_ = std::make_unique<StatusTeePublisher>(next, store_);
  return *tee_;
}

}  // namespace cosmos
