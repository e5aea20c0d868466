#pragma once
// A long run of text made in parallel and written in order: the rows of a CSV, the elements of
// results.json's point arrays. Ranges of `chunk` items are formatted on every worker, a few per
// worker at a time, and handed to `write` in item order as each batch completes. The text is
// the same as formatting [0, count) in one go; the memory held is a few ranges' text, not the
// whole file's (a 10^6-point grid's CSV is about 60 MB).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace luxgrid::report {

// `format(begin, end, text)` appends the text of items [begin, end) to `text` (it may be
// called from any thread, for disjoint ranges, at once); `write(text)` gets the ranges in order.
void write_chunked(std::size_t count, std::size_t chunk,
                   const std::function<void(std::size_t, std::size_t, std::string&)>& format,
                   const std::function<void(std::string_view)>& write);

}  // namespace luxgrid::report
