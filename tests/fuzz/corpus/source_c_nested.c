#define N 4
/* c */ static const float other[2] = {1, 2};
const float lut[2][3][2] = {{{0.5f, -1e-3F}, {0x10, 2.}, {3, 4}}, {{5, 6}, {7, 8}, {9, .5}}}; // x
