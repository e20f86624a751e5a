// A small bitmap font for labels in plots: printable ASCII (32 to 126) on a
// 5 x 9 grid (rows 0-6 above the baseline, rows 7-8 for descenders), drawn
// with a one-column gap between characters.
#pragma once

namespace brdflut::font {

inline constexpr int kGlyphWidth = 5;   // columns of a glyph
inline constexpr int kGlyphHeight = 9;  // rows of a glyph, descenders included
inline constexpr int kCapHeight = 7;    // rows above the baseline
inline constexpr int kAdvance = 6;      // columns from one character to the next

// Whether column x (0..4), row y (0..8) of character c is inked. Characters
// outside printable ASCII are drawn as '?'.
bool glyph_pixel(char c, int x, int y);

// The raw glyph pattern of printable ASCII character c (32..126): rows of
// 5 characters ('#' inked, '.' blank) separated by single spaces, top row
// first; rows missing at the end are blank. nullptr for other characters.
const char* glyph_pattern(char c);

}  // namespace brdflut::font
