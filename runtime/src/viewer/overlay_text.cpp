#include "viewer/overlay_text.hpp"

#include <SDL.h>

#include <algorithm>
#include <cctype>

namespace sdfc::viewer {

namespace {

// Five rows of three pixels, top to bottom, '1' = lit.
struct Glyph {
  char c;
  const char* bits;
};
constexpr Glyph kFont[] = {
    {'0', "111101101101111"}, {'1', "010110010010111"}, {'2', "111001111100111"}, {'3', "111001111001111"},
    {'4', "101101111001001"}, {'5', "111100111001111"}, {'6', "111100111101111"}, {'7', "111001001001001"},
    {'8', "111101111101111"}, {'9', "111101111001111"}, {'A', "010101111101101"}, {'B', "110101110101110"},
    {'C', "011100100100011"}, {'D', "110101101101110"}, {'E', "111100110100111"}, {'F', "111100110100100"},
    {'G', "011100101101011"}, {'H', "101101111101101"}, {'I', "111010010010111"}, {'J', "001001001101010"},
    {'K', "101101110101101"}, {'L', "100100100100111"}, {'M', "101111111101101"}, {'N', "110101101101101"},
    {'O', "010101101101010"}, {'P', "110101110100100"}, {'Q', "010101101110011"}, {'R', "110101110101101"},
    {'S', "011100010001110"}, {'T', "111010010010010"}, {'U', "101101101101111"}, {'V', "101101101101010"},
    {'W', "101101111111101"}, {'X', "101101010101101"}, {'Y', "101101010010010"}, {'Z', "111001010100111"},
    {'.', "000000000000010"}, {':', "000010000010000"}, {'/', "001001010100100"}, {'-', "000000111000000"},
    {'%', "101001010100101"}, {'(', "001010010010001"}, {')', "100010010010100"}, {',', "000000000010100"},
    {'+', "000010111010000"}, {'=', "000111000111000"}, {'_', "000000000000111"},
};

const char* glyph(char c) {
  c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kFont)
    if (g.c == c) return g.bits;
  return nullptr;
}

}  // namespace

void draw_overlay(SDL_Renderer* r, const std::vector<std::string>& lines, int scale) {
  if (lines.empty()) return;
  const int advance = 4 * scale, line_height = 7 * scale, pad = 2 * scale;
  std::size_t longest = 0;
  for (const auto& l : lines) longest = std::max(longest, l.size());
  SDL_Rect panel{0, 0, int(longest) * advance + 2 * pad, int(lines.size()) * line_height + 2 * pad};
  SDL_SetRenderDrawBlendMode(r, SDL_BLENDMODE_BLEND);
  SDL_SetRenderDrawColor(r, 0, 0, 0, 160);
  SDL_RenderFillRect(r, &panel);
  SDL_SetRenderDrawColor(r, 255, 255, 255, 255);
  for (std::size_t li = 0; li < lines.size(); ++li) {
    int y0 = pad + int(li) * line_height;
    for (std::size_t ci = 0; ci < lines[li].size(); ++ci) {
      const char* bits = glyph(lines[li][ci]);
      if (!bits) continue;
      int x0 = pad + int(ci) * advance;
      for (int k = 0; k < 15; ++k)
        if (bits[k] == '1') {
          SDL_Rect px{x0 + (k % 3) * scale, y0 + (k / 3) * scale, scale, scale};
          SDL_RenderFillRect(r, &px);
        }
    }
  }
}

}  // namespace sdfc::viewer
