#include "roadscale/synth/procedural_texture.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "roadscale/synth/colour_math.h"
#include "roadscale/synth/texture_hash.h"

namespace roadscale::synth {
namespace {

double Clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }

Rgb Scale(const Rgb& c, double k) {
  return {static_cast<float>(c.r * k), static_cast<float>(c.g * k), static_cast<float>(c.b * k)};
}

Rgb Grey(double v) {
  const float f = static_cast<float>(v);
  return {f, f, f};
}

// Per-object random number in [0, 1) for choice `k`.
double VariantUnit(uint32_t variant, uint32_t k) {
  return static_cast<double>(Hash32(variant * 0x9e3779b1U + k * 0x85ebca77U) >> 8) / 16777216.0;
}

// A pulse of the train (period, width, offset) that the point falls into, for per-cell
// random shades: index of the cell containing x.
int64_t CellIndex(double x, double period, double offset) {
  return static_cast<int64_t>(FastFloor((x - offset) / period));
}

// A 2-D box-filtered rectangle-grid: cells of size (period_s, period_t) with a rectangle of
// (width_s, width_t) in each.
double FilteredGrid(const TexelQuery& q, double period_s, double width_s, double offset_s,
                    double period_t, double width_t, double offset_t) {
  return FilteredPulse(q.s, period_s, width_s, offset_s, q.footprint_s) *
         FilteredPulse(q.t, period_t, width_t, offset_t, q.footprint_t);
}

// Thin dark lines along the zero set of a noise field (cracks, seams), filtered.
double Cracks(double s, double t, double footprint, double frequency, double width, uint32_t seed) {
  const double warp = FilteredFbm(s, t, footprint, frequency * 2.0, 2, 0.5, seed + 7);
  const double n = ValueNoise(s * frequency + warp, t * frequency - warp, seed) - 0.5;
  // |n| grows roughly by `frequency` per metre away from the crack.
  const double distance = std::abs(n) / (frequency * 1.3);
  const double blur = 0.5 * footprint + 0.002;
  return SmoothStep(width + blur, width - blur, distance) * std::min(1.0, width / blur);
}

// Sparse stains (oil drops, dust, filled holes, manhole covers): at most one ellipse per
// cell of cell_s x cell_t, inside it, with probability `density`; the ellipse is `aspect`
// times longer along s (the road) than across, with an across-road radius in
// [r_min, r_max]. Returns the filtered coverage of the ellipse grown by `grow` (metres
// across), and in `sign` whether the stain is dark (-1) or light (+1).
double Spots(const TexelQuery& q, double cell_s, double cell_t, double aspect, double density,
             double r_min, double r_max, double light_share, uint32_t seed, double* sign,
             double grow = 0.0) {
  const int32_t ci = static_cast<int32_t>(FastFloor(q.s / cell_s));
  const int32_t cj = static_cast<int32_t>(FastFloor(q.t / cell_t));
  const uint32_t h = Hash3(ci, cj, seed);
  if (static_cast<double>(h >> 8) / 16777216.0 >= density) return 0.0;
  auto unit = [&](uint32_t k) { return (Hash32(h + k) >> 8) / 16777216.0; };
  const double radius = r_min + (r_max - r_min) * unit(0);
  const double margin_t = std::min(radius + grow, 0.5 * cell_t);
  const double margin_s = std::min(aspect * (radius + grow), 0.5 * cell_s);
  const double cs = ci * cell_s + margin_s + (cell_s - 2.0 * margin_s) * unit(1);
  const double ct = cj * cell_t + margin_t + (cell_t - 2.0 * margin_t) * unit(2);
  *sign = unit(3) < light_share ? 1.0 : -1.0;
  // Distance in units of the across-road radius; the footprint scaled the same way.
  const double ds = (q.s - cs) / aspect, dt = q.t - ct;
  const double d = std::sqrt(ds * ds + dt * dt);
  const double r = radius + grow;
  const double soft = 0.5 * std::max(q.footprint_s / aspect, q.footprint_t) + 0.004;
  return SmoothStep(r + soft, r - soft, d) * std::min(1.0, r / soft);
}

// Rectangular repairs (utility cuts) aligned with the road: at most one per cell of
// cell_s x cell_t. Returns the filtered coverage, the patch's shade in [-1, 1] and, in
// `edge`, the coverage of its 4 cm tar-sealed border.
double Repairs(const TexelQuery& q, double cell_s, double cell_t, double density, uint32_t seed,
               double* shade, double* edge) {
  *edge = 0.0;
  const int32_t ci = static_cast<int32_t>(FastFloor(q.s / cell_s));
  const int32_t cj = static_cast<int32_t>(FastFloor(q.t / cell_t));
  const uint32_t h = Hash3(ci, cj, seed);
  if (static_cast<double>(h >> 8) / 16777216.0 >= density) return 0.0;
  auto unit = [&](uint32_t k) { return (Hash32(h + k) >> 8) / 16777216.0; };
  const double length = cell_s * (0.2 + 0.6 * unit(1));
  const double width = cell_t * (0.2 + 0.6 * unit(2));
  const double s0 = ci * cell_s + (cell_s - length) * unit(3);
  const double t0 = cj * cell_t + (cell_t - width) * unit(4);
  *shade = 2.0 * unit(5) - 1.0;
  const double inside = FilteredBox(q.s, s0, s0 + length, q.footprint_s) *
                        FilteredBox(q.t, t0, t0 + width, q.footprint_t);
  const double border = 0.04;
  const double outer = FilteredBox(q.s, s0 - border, s0 + length + border, q.footprint_s) *
                       FilteredBox(q.t, t0 - border, t0 + width + border, q.footprint_t);
  *edge = outer - inside;
  return inside;
}

Rgb Asphalt(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context) {
  const TextureOptions& options = context.options;
  const uint32_t seed = context.seed ^ 0xa5f1u;
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const double contrast = options.road_contrast;
  // Large stains, medium blotches and a fine grain that fades with distance, as real
  // asphalt does in a camera image.
  const double stains = FilteredFbm(q.s, q.t, fp, 0.05, 2, 0.5, seed);
  const double blotch = FilteredFbm(q.s, q.t, fp, 0.5, 2, 0.6, seed + 5);
  const double grain = FilteredFbm(q.s, q.t, fp, 3.0, 5, 0.85, seed + 11);
  double v = 1.0 + contrast * (0.25 * stains + 0.12 * blotch + 1.2 * grain);
  // Detail that gives the road its few, strong corners: repairs with sealed edges, stains,
  // manhole covers, cracks.
  const double detail = options.road_detail;
  if (detail > 0.0) {
    double shade = 0.0, edge = 0.0;
    const double repair = Repairs(q, 9.0, 3.5, 0.45 * detail, seed + 23, &shade, &edge);
    v *= (1.0 + contrast * 0.2 * repair * shade) * (1.0 - contrast * 0.45 * edge);
    // Stains drawn out along the road (drips from passing cars, wheel-borne dirt): seen
    // from the car they look round, which is what blob detectors such as SIFT pick up.
    double sign = 0.0;
    const double drips = Spots(q, 3.2, 0.8, 4.0, 0.35 * detail, 0.04, 0.14, 0.3, seed + 29, &sign);
    v *= 1.0 + contrast * (sign < 0.0 ? 0.35 : 0.25) * sign * drips;
    // Larger streaks for the distance, where the road is seen at a grazing angle.
    const double streaks =
        Spots(q, 10.0, 1.75, 8.0, 0.6 * detail, 0.1, 0.25, 0.2, seed + 59, &sign);
    v *= 1.0 + contrast * 0.4 * sign * streaks;
    const double spots = Spots(q, 1.0, 1.0, 1.0, 0.3 * detail, 0.03, 0.1, 0.0, seed + 53, &sign);
    v *= 1.0 - contrast * 0.3 * spots;
    // Manhole covers: a dark lid in a light frame.
    const double lid = Spots(q, 25.0, 3.5, 1.0, 0.25 * detail, 0.3, 0.3, 0.0, seed + 61, &sign);
    const double frame =
        Spots(q, 25.0, 3.5, 1.0, 0.25 * detail, 0.3, 0.3, 0.0, seed + 61, &sign, 0.05) - lid;
    v *= (1.0 - contrast * 0.4 * lid) * (1.0 + contrast * 0.4 * frame);
    // Gravel specks, light and dark: the texture a camera resolves near the car.
    const double specks =
        Spots(q, 0.2, 0.2, 1.0, 0.35 * detail, 0.008, 0.025, 0.5, seed + 43, &sign);
    v *= 1.0 + contrast * 0.6 * sign * specks;
    const double crack = Cracks(q.s, q.t, fp, 0.18, 0.02, seed + 31);
    const double crack_density = SmoothStep(0.45 - 0.12 * detail, 0.65 - 0.12 * detail,
                                            ValueNoise(q.s * 0.03, q.t * 0.1, seed + 37));
    v *= 1.0 - contrast * 0.5 * crack * crack_density;
  }
  Rgb colour = Scale(style.tint, v);
  // Lane markings: box-filtered across and along the road.
  for (const LaneMarking& m : context.markings) {
    if (std::abs(q.t - m.l) > m.width + q.footprint_t) continue;
    double cover = FilteredBox(q.t, m.l - 0.5 * m.width, m.l + 0.5 * m.width, q.footprint_t);
    if (m.gap > 0.0) cover *= FilteredPulse(q.s, m.dash + m.gap, m.dash, 0.0, q.footprint_s);
    const double wear = 0.8 + 0.2 * FilteredFbm(q.s, q.t, fp, 3.0, 3, 0.6, seed + 41);
    colour = Mix(colour, Grey(0.78 * wear), cover);
  }
  return colour;
}

Rgb Paving(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context,
           double slab_s, double slab_t) {
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const uint32_t seed = context.seed ^ 0x5e1du ^ style.variant;
  const double joint = 0.012;
  const double slab_area =
      FilteredGrid(q, slab_s, slab_s - joint, 0.0, slab_t, slab_t - joint, 0.0);
  const int64_t cell_s = CellIndex(q.s, slab_s, 0.0);
  const int64_t cell_t = CellIndex(q.t, slab_t, 0.0);
  const double slab_shade =
      (HashUnit(static_cast<int32_t>(cell_s), static_cast<int32_t>(cell_t), seed) - 0.5) *
      std::min(1.0, slab_s / (fp + 1e-9) * 0.5);
  const double grain = FilteredFbm(q.s, q.t, fp, 2.0, 4, 0.6, seed + 3);
  const double v = (0.80 + 0.20 * slab_area) * (1.0 + 0.12 * slab_shade + 0.35 * grain);
  return Scale(style.tint, v);
}

Rgb Brick(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context);

// One window of a facade at local coordinates (x, y) from its lower left corner, size
// (w, h): glass with a mullion and a transom, curtains or blinds behind it. Returns the
// colour to blend over the wall and its coverage.
double WindowPane(const TexelQuery& q, double x, double y, double w, double h, uint32_t cell,
                  double contrast, Rgb* colour) {
  const double fs = q.footprint_s, ft = q.footprint_t;
  auto inside = [&](double a0, double a1, double b0, double b1) {
    return FilteredBox(x, a0, a1, fs) * FilteredBox(y, b0, b1, ft);
  };
  const double cover = inside(-0.08, w + 0.08, -0.08, h + 0.08);
  if (cover <= 0.0) return 0.0;
  auto unit = [&](uint32_t k) { return (Hash32(cell * 0x27d4eb2dU + k) >> 8) / 16777216.0; };
  // Glass: dark, with the sky's reflection brighter towards the top.
  double v = 0.08 + 0.18 * unit(1) + 0.12 * std::clamp(y / h, 0.0, 1.0);
  // Curtains on one side, or a blind pulled part way down, in some windows.
  const double curtain = unit(2);
  if (curtain < 0.35) {
    const double left = unit(3) < 0.5 ? 1.0 : 0.0;
    const double width = w * (0.2 + 0.25 * unit(4));
    const double c = left > 0.0 ? inside(0.0, width, 0.0, h) : inside(w - width, w, 0.0, h);
    v += (0.45 + 0.3 * unit(5) - v) * c;
  } else if (curtain < 0.55) {
    const double down = h * (0.15 + 0.6 * unit(6));
    const double slats = FilteredPulse(y, 0.05, 0.035, 0.0, ft);
    v += (0.5 + 0.15 * slats - v) * inside(0.0, w, h - down, h);
  }
  // Mullion, transom, frame, sill.
  const double frame = 1.0 - inside(0.0, w, 0.0, h);
  const double bars = std::max(inside(0.5 * w - 0.03, 0.5 * w + 0.03, 0.0, h),
                               inside(0.0, w, 0.68 * h - 0.03, 0.68 * h + 0.03));
  const double light = 0.82 + 0.1 * unit(7);
  v += (light - v) * std::max(frame, bars);
  const double sill = inside(-0.12, w + 0.12, -0.14, -0.06);
  *colour = Grey(std::clamp(1.0 + contrast * (v - 1.0), 0.0, 1.0));
  return std::max(cover, sill) * std::min(1.0, contrast);
}

Rgb Facade(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context) {
  const double contrast = context.options.facade_contrast;
  const uint32_t v = style.variant;
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const double floor_height = 3.0 + 0.6 * VariantUnit(v, 1);
  const double spacing = 2.4 + 1.4 * VariantUnit(v, 2);
  const double window_w = std::min(spacing - 0.7, 0.9 + 0.6 * VariantUnit(v, 3));
  const double window_h = 1.2 + 0.5 * VariantUnit(v, 4);
  const double sill = 0.9;
  const double ground_floor = floor_height + 0.5 * VariantUnit(v, 5);
  const double offset_s = spacing * VariantUnit(v, 6);
  const uint32_t seed = context.seed ^ 0xfacau ^ v;

  // The wall: brick on some buildings, plaster with grime and fine grain on the others.
  Rgb colour;
  if (VariantUnit(v, 9) < 0.25) {
    colour = Brick(style, q, context);
  } else {
    const double grime = FilteredFbm(q.s, q.t, fp, 0.3, 3, 0.55, seed);
    const double grain = FilteredFbm(q.s, q.t, fp, 6.0, 3, 0.8, seed + 3);
    colour = Scale(style.tint, 1.0 + contrast * (0.2 * grime + 0.12 * grain));
  }
  // A dark plinth and a cornice line per floor.
  const double plinth = FilteredBox(q.t, -0.3, 0.3, q.footprint_t);
  colour = Scale(colour, 1.0 - contrast * 0.25 * plinth);
  const double cornice =
      FilteredPulse(q.t, floor_height, 0.15, ground_floor - 0.15, q.footprint_t) *
      (q.t > ground_floor - 0.3 ? 1.0 : 0.0);
  colour = Scale(colour, 1.0 + contrast * 0.12 * cornice);

  if (q.t > ground_floor) {
    // Upper floors: a grid of windows.
    const double t0 = ground_floor + sill;
    const int64_t cs = CellIndex(q.s, spacing, offset_s - 0.5 * (spacing - window_w));
    const int64_t ct = CellIndex(q.t, floor_height, t0 - 0.5 * (floor_height - window_h));
    const double x = q.s - (offset_s + cs * spacing);
    const double y = q.t - (t0 + ct * floor_height);
    Rgb pane;
    const uint32_t cell = Hash3(static_cast<int32_t>(cs), static_cast<int32_t>(ct), seed);
    const double k = WindowPane(q, x, y, window_w, window_h, cell, contrast, &pane);
    colour = Mix(colour, pane, k);
  } else if (q.t > 0.0) {
    // Ground floor: wide shop windows and doors.
    const double shop_w = 1.2 + 2.0 * VariantUnit(v, 7);
    const double period = shop_w + 0.8 + 1.5 * VariantUnit(v, 8);
    const int64_t cs = CellIndex(q.s, period, offset_s - 0.4);
    const double x = q.s - (offset_s + cs * period);
    Rgb pane;
    const uint32_t cell = Hash3(static_cast<int32_t>(cs), -1, seed);
    const double k = WindowPane(q, x, q.t - 0.5, shop_w, ground_floor - 0.9, cell, contrast, &pane);
    colour = Mix(colour, pane, k);
  }
  return colour;
}

Rgb Brick(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context) {
  const double contrast = context.options.facade_contrast;
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const double course = 0.075;
  const double row = FastFloor(q.t / course);
  const double shift = std::fmod(row, 2.0) == 0.0 ? 0.0 : 0.125;
  const double mortar_t = 1.0 - FilteredPulse(q.t, course, course - 0.012, 0.0, q.footprint_t);
  const double mortar_s = 1.0 - FilteredPulse(q.s, 0.25, 0.238, shift, q.footprint_s);
  const double mortar = std::max(mortar_t, mortar_s * (1.0 - mortar_t));
  const double brick_shade = HashUnit(static_cast<int32_t>(CellIndex(q.s, 0.25, shift)),
                                      static_cast<int32_t>(row), style.variant) -
                             0.5;
  const double fade = std::min(1.0, course / (fp + 1e-9) * 0.5);
  const double grain = FilteredFbm(q.s, q.t, fp, 0.5, 3, 0.6, style.variant + 5);
  double v = 1.0 + contrast * (0.2 * brick_shade * fade + 0.2 * grain);
  Rgb colour = Scale(style.tint, v);
  return Mix(colour, Grey(0.62), contrast * 0.7 * mortar);
}

Rgb Concrete(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context) {
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const double stain = FilteredFbm(q.s, q.t, fp, 0.3, 4, 0.6, context.seed ^ style.variant);
  const double joints = 1.0 - FilteredPulse(q.s, 2.0, 1.98, 0.0, q.footprint_s);
  return Scale(style.tint, (1.0 + 0.3 * stain) * (1.0 - 0.35 * joints));
}

Rgb Fence(const SurfaceStyle& style, const TexelQuery& q) {
  const double slat = FilteredPulse(q.s, 0.14, 0.09, 0.0, q.footprint_s);
  const double rail =
      FilteredBox(q.t, 0.25, 0.33, q.footprint_t) + FilteredBox(q.t, 1.1, 1.18, q.footprint_t);
  const double solid = std::min(1.0, slat + rail);
  return Mix(Grey(0.12), style.tint, solid);
}

Rgb Foliage(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context) {
  const double contrast = context.options.vegetation_contrast;
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const uint32_t seed = context.seed ^ 0xf011u ^ style.variant;
  const double clumps = FilteredFbm(q.s, q.t, fp, 0.6, 3, 0.5, seed);
  const double leaves = FilteredFbm(q.s, q.t, fp, 6.0, 4, 0.7, seed + 9);
  // Dark gaps between leaf clumps give the strong, dense corners of real trees.
  const double gaps = SmoothStep(0.05, -0.15, leaves + 0.6 * clumps);
  const double v = (1.0 + contrast * (0.5 * clumps + 0.8 * leaves)) * (1.0 - 0.6 * contrast * gaps);
  return Scale(style.tint, std::max(0.05, v));
}

Rgb Grass(const SurfaceStyle& style, const TexelQuery& q, const TextureContext& context) {
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const uint32_t seed = context.seed ^ 0x64a5u;
  const double low = FilteredFbm(q.s, q.t, fp, 0.1, 3, 0.5, seed);
  const double blades = FilteredFbm(q.s, q.t, fp, 4.0, 4, 0.75, seed + 3);
  return Scale(style.tint, 1.0 + context.options.vegetation_contrast * (0.4 * low + 0.6 * blades));
}

Rgb Bark(const SurfaceStyle& style, const TexelQuery& q) {
  const double fp = std::max(q.footprint_s, q.footprint_t);
  const double n = FilteredFbm(q.s * 6.0, q.t, fp * 6.0, 1.0, 4, 0.6, style.variant);
  return Scale(style.tint, 1.0 + 0.6 * n);
}

Rgb CarPaint(const SurfaceStyle& style, const TexelQuery& q) {
  const double fp = std::max(q.footprint_s, q.footprint_t);
  // Door seams, a dark bumper strip at the bottom and a trim line under the windows.
  const double seams = 1.0 - FilteredPulse(q.s, 1.1, 1.08, 0.3, q.footprint_s);
  const double bumper = FilteredBox(q.t, -1.0, 0.1, q.footprint_t);
  const double n = FilteredFbm(q.s, q.t, fp, 1.0, 3, 0.5, style.variant);
  Rgb colour = Scale(style.tint, (1.0 + 0.1 * n) * (1.0 - 0.5 * seams));
  return Mix(colour, Grey(0.08), 0.8 * bumper);
}

Rgb CarGlass(const SurfaceStyle& style, const TexelQuery& q) {
  // Pillars between the side windows and a reflection that brightens upward.
  const double pillar = 1.0 - FilteredPulse(q.s, 1.2, 1.05, 0.12, q.footprint_s);
  const double v = 0.1 + 0.25 * Clamp01(q.t / 0.6);
  return Mix(Grey(v), style.tint, pillar);
}

Rgb Tyre(const SurfaceStyle& style, const TexelQuery& q) {
  // A light rim on the wheel's side faces (0.62 m square, hub at the centre).
  const double r = std::sqrt((q.s - 0.31) * (q.s - 0.31) + (q.t - 0.31) * (q.t - 0.31));
  const double soft = 0.5 * std::max(q.footprint_s, q.footprint_t) + 0.005;
  const double rim = std::clamp((0.19 + soft - r) / (2.0 * soft), 0.0, 1.0);
  return Mix(style.tint, Grey(0.45), rim);
}

Rgb Sign(const SurfaceStyle& style, const TexelQuery& q) {
  const double inner =
      FilteredBox(q.s, 0.05, 0.55, q.footprint_s) * FilteredBox(q.t, 0.05, 0.55, q.footprint_t);
  return Mix(Grey(0.2), style.tint, inner);
}

Rgb Cloth(const SurfaceStyle& style, const TexelQuery& q) {
  const double fp = std::max(q.footprint_s, q.footprint_t);
  return Scale(style.tint, 1.0 + 0.2 * FilteredFbm(q.s, q.t, fp, 3.0, 3, 0.5, style.variant));
}

// The sum of the octaves' amplitudes. Every texel asks for one of the few (gain, octaves)
// pairs the materials use, and std::pow recomputed it each time (a tenth of a render's perf
// samples; cached, a render takes 3-4 % less CPU): each thread keeps the last pairs' values,
// the same doubles std::pow gives, so the frames do not change.
double FbmNorm(double gain, int octaves) {
  struct Entry {
    double gain = -1.0;
    int octaves = -1;
    double norm = 0.0;
  };
  constexpr size_t kEntries = 8;
  thread_local std::array<Entry, kEntries> cache;
  thread_local size_t next = 0;
  for (const Entry& entry : cache) {
    if (entry.gain == gain && entry.octaves == octaves) return entry.norm;
  }
  const double norm = gain == 1.0 ? octaves : (1.0 - std::pow(gain, octaves)) / (1.0 - gain);
  cache[next] = {gain, octaves, norm};
  next = (next + 1) % kEntries;
  return norm;
}

}  // namespace

double FilteredFbm(double x, double y, double footprint, double frequency, int octaves, double gain,
                   uint32_t seed) {
  // The norm counts every octave, filtered or not, so that the variance falls with
  // distance as it does in a properly filtered texture.
  const double norm = FbmNorm(gain, octaves);
  double sum = 0.0, amplitude = 1.0;
  for (int o = 0; o < octaves; ++o) {
    // Full weight while a cell spans four footprints, none below two.
    const double fade = Clamp01(2.0 - 4.0 * footprint * frequency);
    if (fade <= 0.0) break;
    // Offsets keep the lattices of different octaves from lining up.
    sum += amplitude * fade *
           (ValueNoise(x * frequency + 17.31 * o, y * frequency - 9.73 * o, seed + o * 101u) - 0.5);
    frequency *= 2.0;
    amplitude *= gain;
  }
  return norm > 0.0 ? sum / norm * 1.6 : 0.0;
}

double FilteredPulse(double x, double period, double width, double offset, double footprint) {
  auto integral = [&](double v) {
    const double shifted = v - offset;
    const double k = FastFloor(shifted / period);
    return k * width + std::min(shifted - k * period, width);
  };
  if (footprint < 1e-6) {
    const double shifted = x - offset;
    const double phase = shifted - FastFloor(shifted / period) * period;
    return phase < width ? 1.0 : 0.0;
  }
  return (integral(x + 0.5 * footprint) - integral(x - 0.5 * footprint)) / footprint;
}

Rgb MaterialAlbedo(const SurfaceStyle& style, const TexelQuery& query,
                   const TextureContext& context) {
  switch (style.material) {
    case Material::kAsphalt:
      return Asphalt(style, query, context);
    case Material::kSidewalk:
      return Paving(style, query, context, 0.3, 0.3);
    case Material::kPaving:
      return Paving(style, query, context, 0.6, 0.4);
    case Material::kKerb:
      return Concrete(style, query, context);
    case Material::kGrass:
      return Grass(style, query, context);
    case Material::kFacade:
      return Facade(style, query, context);
    case Material::kRoof: {
      const double rows = FilteredPulse(query.t, 0.3, 0.26, 0.0, query.footprint_t);
      return Scale(style.tint, 0.8 + 0.2 * rows);
    }
    case Material::kBrick:
      return Brick(style, query, context);
    case Material::kConcrete:
      return Concrete(style, query, context);
    case Material::kFence:
      return Fence(style, query);
    case Material::kFoliage:
      return Foliage(style, query, context);
    case Material::kBark:
      return Bark(style, query);
    case Material::kMetal:
      return style.tint;
    case Material::kCarPaint:
      return CarPaint(style, query);
    case Material::kCarGlass:
      return CarGlass(style, query);
    case Material::kTyre:
      return Tyre(style, query);
    case Material::kCloth:
      return Cloth(style, query);
    case Material::kSkin:
      return style.tint;
    case Material::kSign:
      return Sign(style, query);
  }
  return style.tint;
}

}  // namespace roadscale::synth
