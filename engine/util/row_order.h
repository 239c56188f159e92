#pragma once
// GL's first row is the bottom one; image files, the window's pixels and everything the user is
// shown count rows from the top. Every flip between the two goes through here.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace penumbra {

// Row `row` of an image `height` rows tall, counted from the other end.
constexpr int flipped_row(int row, int height) { return height - 1 - row; }

// `rows` rows of `row_bytes` each, in the other order (bottom-up <-> top-down).
template <class T>
std::vector<T> rows_flipped(const std::vector<T>& data, size_t row_length, int rows) {
  std::vector<T> out(data.size());
  for (int y = 0; y < rows; ++y)
    std::copy_n(&data[static_cast<size_t>(flipped_row(y, rows)) * row_length], row_length, &out[static_cast<size_t>(y) * row_length]);
  return out;
}

}  // namespace penumbra
