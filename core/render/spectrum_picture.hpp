#pragma once
// spectrum.png: the shape spectrum (§3.2.3) as a histogram over S_I in [0, 1], bars coloured by
// their Fig. 3.3 category with the category boundaries marked, the planar fraction as its own
// bar on the right (on its own 0-100 % axis, since it often dwarfs every curved bin), and the
// first moments (Eqs. 4.1-4.2) in the title.
#include "core/render/bgr_picture.hpp"
#include "core/representation/shape_spectrum.hpp"

namespace cosmos {

inline constexpr int kSpectrumWidthPx = 1000;
inline constexpr int kSpectrumHeightPx = 560;

BgrPicture render_spectrum_picture(const ShapeSpectrum& spectrum, const MomentVector& moments);

}  // namespace cosmos
