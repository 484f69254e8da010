// nbscope render: what the window shows over the scene, built from plain data into a DrawSink:
// bodies, the elements' bounding circles, the cell grid with occupancy, the detector's singly
// connected lists as arrow chains, the contact mask of the hovered cell, detected pairs, check
// results, the selection, trails and cell-change flashes. No GL here: a recorder sees the same calls.
//
// Index: ShapeDraw (bodies) | CheckDraw | OverlayFlags (+ keys) | ListFilter | OverlayScene | draw_scene.
// The grid, its heat map and the legend are drawn in overlay_grid.cpp, the lists in overlay_lists.cpp,
// a verify run's red marks in overlay_verify.cpp.
#pragma once
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/layers.hpp"
#include "core/pairs.hpp"
#include "core/subdomain_grid.hpp"
#include "render/camera.hpp"
#include "render/colour_map.hpp"
#include "render/draw_sink.hpp"
#include "render/label_space.hpp"
#include "render/overlay_layers.hpp"
#include "core/traced_lists.hpp"
#include "render/overlay_verify.hpp"

namespace nbscope::render {

// How a body moves (colours differ).
enum class Motion : std::uint8_t { Static, Kinematic, Dynamic };

// One fixture to draw: a circle (centre, radius, angle for the spoke) or a convex polygon whose
// world-space corners are points[first, first + count) of OverlayScene::shape_points.
struct ShapeDraw {
  Motion motion = Motion::Dynamic;
  bool is_circle = true;
  Vec2 centre{0, 0};
  float radius = 0;
  float angle = 0;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  ElementId element = -1;  // its bounding circle's element id
  bool spoke = true;       // a circle's rotation drawn as a spoke (false: a plain element, no body behind it)
};

// The frame's check results, as pairs of element ids (i < j).
struct CheckDraw {
  PairList confirmed;        // detected and touching per Box2D at the same positions (sorted)
  PairList broadphase_only;  // in Box2D's broadphase (fat AABBs overlap) but not detected
  PairList violations;       // any broken invariant: wrong, missing or unconfirmed pairs
};

// Which overlays are on. Each has a key (see kOverlayKeys) and a checkbox in the Overlays panel.
struct OverlayFlags {
  bool bodies = true;
  bool elements = false;    // bounding circles
  bool grid = true;         // cells in view, occupied cells shaded by count, nx x ny
  bool lists = false;       // the detector's lists as arrow chains (needs a traced detection)
  bool mask = true;         // the contact mask of the hovered cell (else the selected element's)
  bool pairs = true;        // detected pairs
  bool checks = true;       // confirmed pairs and violations
  bool broadphase = false;  // Box2D-only broadphase pairs (fat AABBs)
  bool ids = false;         // element ids, inside the circle or beside it, never over another label
  bool trails = true;       // trails of selected elements
  bool flash = true;        // elements that changed cell this frame
  bool subdomains = true;   // each MPI rank's subdomain (a frame read from per-rank dumps; others have none)
};

// One overlay's name, key and flag, for panels, key handling and settings.
struct OverlayInfo {
  const char* name;      // settings key and label
  char key;              // upper-case letter (GLFW and ImGui 1.86 key code of that letter)
  bool OverlayFlags::*flag;
  const char* help;
};
// All overlays in panel order.
std::span<const OverlayInfo> overlay_infos();
// Sets one overlay; turning the lists on turns the ids on too (the lists read by them), and I alone
// turns the ids off again: ids are drawn only while `ids` is on.
void set_overlay(OverlayFlags& flags, bool OverlayFlags::*flag, bool on);

// Which lists the lists overlay draws.
enum class ListFilter : std::uint8_t {
  All,       // every list
  Selected,  // the lists that hold the selected element
  Row,       // the lists of the hovered row, else the stepper's row, else the selected element's row (none: see kAllListsUpTo)
};
// Settings and flag names of the filters, in enum order.
inline constexpr const char* kListFilterNames[] = {"all", "selected", "row"};
// Elements above which the filter defaults to Row: past it all lists together are a tangle.
inline constexpr std::int64_t kRowFilterAbove = 300;
// Row with no row hovered, stepped or selected draws every list up to this many elements (where
// the filter starts on All anyway), none beyond: pile.json's 1,621 elements' lists all at once are a
// hairball, and the legend says how to choose a row instead.
inline constexpr std::int64_t kAllListsUpTo = kRowFilterAbove;
// Cells narrower than this on screen (pixels) switch the grid to its overview: major lines and a
// heat map of elements per cell, drawn over the bodies.
inline constexpr double kHeatMapBelowPx = 6.0;

// Everything one frame's overlays are drawn from; null/empty members are simply not drawn.
struct OverlayScene {
  const Elements* elements = nullptr;
  const Grid* grid = nullptr;
  std::span<const ShapeDraw> shapes;
  std::span<const Vec2> shape_points;
  const PairList* pairs = nullptr;               // A, sorted (i, j)
  const CheckDraw* checks = nullptr;
  const std::vector<TracedList>* lists = nullptr;  // from traced_lists()
  ElementId selected = -1;
  std::optional<Pair> focus_pair;  // a violation's pair gone to: both elements, their cells and the segment marked
  std::optional<std::array<std::int32_t, 2>> hovered_cell;
  std::optional<std::int32_t> focus_row;  // the row whose secondary (row-below) lists are shown
  ListFilter list_filter = ListFilter::All;
  // The stepper's current operation, mid-trace: the list being written (heads array, slot) and the
  // pair being tested (with its result), drawn highlighted by the lists overlay.
  std::optional<std::pair<int, std::int64_t>> active_list;
  std::optional<Pair> tested_pair;
  bool tested_contact = false;
  // Lines the legend says about the lists ("lists at operation 3 of 91", "brute keeps no lists").
  std::vector<std::string> lists_caption;
  std::span<const std::vector<Vec2>> trails;
  std::span<const std::pair<ElementId, float>> flashes;  // element, strength in (0, 1]
  std::optional<std::array<Vec2, 2>> drag;               // body anchor -> mouse while dragging
  ScreenInsets insets;         // pixels at the view's edges covered by panels: the grid's numbers and list heads keep clear
  std::span<const PixelRect> covered;  // the panels' windows and the menu bar: no label is drawn under them
  bool book_numbering = false;  // element ids and cell indices drawn from 1, as the book prints them
  // The run's length unit after the grid's cell size ("sigma": d = 1.2 sigma); empty for none (a scene's metres).
  std::string length_unit;
  // The atom id of each row (a dump's frame, io/recording.hpp): the ids overlay shows these instead.
  const std::vector<std::int64_t>* ids = nullptr;
  // Someone's own arrays checked (nbscope verify --arrays): `lists` are theirs, these are the
  // problems found, drawn in red over them (wrong links, elements ringed, cut lists' ends).
  const VerifyMarks* verify = nullptr;
  // A 3D frame is shown one layer of cells at a time (core/layers.hpp): the elements of `layer->layer`
  // as in 2D, those of the layer below (which the mask reaches) ghosted, the others hidden; lists,
  // pairs, checks and the mask of this layer and the one below. Null for a 2D frame.
  const LayerSlice* layer = nullptr;
  // --color-by: each element's fill (by row; empty: the bodies' own colours) and what they mean (the legend's).
  std::span<const Rgba> element_fills;
  const ColourKey* colour_key = nullptr;
  // Each MPI rank's subdomain (a frame read from per-rank dumps: core/subdomain_grid.hpp), or null.
  const Subdomains* subdomains = nullptr;
};

// The row whose lists the Row filter keeps (and whose row-below copies are drawn): the stepper's row
// while it is mid-frame (the lists it is building must not jump to wherever the mouse is), else the
// hovered cell's, else the selected element's; none when none of them is given.
[[nodiscard]] std::optional<std::int32_t> list_focus_row(std::optional<std::int32_t> stepper_row,
                                                         std::optional<std::array<std::int32_t, 2>> hovered_cell,
                                                         std::optional<std::int32_t> selected_row);

// The colour of a list of kind `kind` ("y-list", "x-list", "cell list", ...), or of the row below's
// copies (NBS's B[1]); the stepper's scene overlay uses the same.
[[nodiscard]] Rgba list_colour(std::string_view kind, bool row_below);

// Draws the scene and every overlay `flags` turns on, seen through `camera`.
void draw_scene(const OverlayScene& scene, const OverlayFlags& flags, const Camera& camera, DrawSink& sink);

// The element whose bounding circle contains `world` (the smallest such; ties: lowest id), or -1.
ElementId element_at(const Elements& elements, const Eigen::Vector2d& world);

// The cells of the contact mask of cell (ix, iy): the cell itself first, then its half mask (book: NBS).
std::vector<std::array<std::int32_t, 2>> mask_cells(const Grid& grid, std::int32_t ix, std::int32_t iy);

}  // namespace nbscope::render
