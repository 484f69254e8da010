// nbscope ui: the step-through panels — Stepper (walk the paused frame's detection one book
// operation at a time), Arrays (the heads and next arrays as the book's figures draw them) and
// Pseudocode (the detector's loops with the current line and its loop variables) — and their scene
// overlay (the current element, the list being built, the mask cell, the pair being tested).
#pragma once
#include <memory>

#include "ui/host.hpp"
#include "ui/stepper_session.hpp"

namespace nbscope::ui {

// Panel titles (also their keys in the settings file and UiState::panel_open).
inline constexpr const char* kStepperTitle = "Stepper";
inline constexpr const char* kArraysTitle = "Arrays";
inline constexpr const char* kPseudocodeTitle = "Pseudocode";
inline constexpr const char* kLayersTitle = "Layers";

// Adds the three panels and the Layers panel (a 3D frame's), sharing one session, to `host`; returns the session (the app configures
// nothing else: `config.step` makes a headless run show the state after that many events).
std::shared_ptr<StepperSession> add_stepper_panels(UiHost& host, StepperConfig config = {});
// Opens the three panels in `state` (headless --step shows them whatever the settings say).
void open_stepper_panels(UiState& state);

// The panels, one file each.
std::unique_ptr<Panel> make_stepper_panel(std::shared_ptr<StepperSession> session);
std::unique_ptr<Panel> make_arrays_panel(std::shared_ptr<StepperSession> session);
std::unique_ptr<Panel> make_pseudocode_panel(std::shared_ptr<StepperSession> session);
// A 3D frame's layers: the layer shown (slider, Up/Down, auto), the side view, the z-lists (from
// the session's arrays while it steps through the frame shown). Hidden for a 2D frame.
std::unique_ptr<Panel> make_layers_panel(std::shared_ptr<StepperSession> session);
// Draws the session's current event into the scene (used by the Stepper panel); with `lists_drawn`
// the lists overlay already draws the list being written, highlighted, so its chain is left out;
// with `layer` (a 3D frame's layer view) only what the view shows: the layer below fainter, the rest not;
// with `ids_drawn` (the ids overlay on) the ringed elements get no id of their own.
void draw_stepper_scene(const StepperSession& session, render::DrawSink& sink, bool lists_drawn = false,
                        const LayerSlice* layer = nullptr, bool ids_drawn = false);

}  // namespace nbscope::ui
