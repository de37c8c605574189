#pragma once
// The bench charts' colours, one per method in the order it first appears (black first).
namespace aokit {

inline constexpr unsigned char kChartColors[8][3] = {{0, 0, 0},      {214, 39, 40},   {31, 119, 180}, {44, 160, 44},
                                                     {255, 127, 14}, {148, 103, 189}, {140, 86, 75},  {227, 119, 194}};

}  // namespace aokit
