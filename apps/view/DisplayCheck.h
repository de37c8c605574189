#pragma once
// VTK aborts the process on an X display it cannot open; the viewer says so in one line first.
// (Xlib's macros stay in DisplayCheck.cpp.)
namespace aokit::view {

// Throws std::runtime_error naming the display when none is set or it cannot be opened.
void requireDisplay();

}  // namespace aokit::view
