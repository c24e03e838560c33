#pragma once
// Html: gathers figures into a directory with an index.html that shows each
// SVG file with its caption (a light report of a run, e.g. of the examples).
#include <string>
#include <vector>

#include "sillage/figures/figure.h"

namespace sillage {

class Html {
 public:
  // An empty page with this title.
  explicit Html(std::string title) : title_(std::move(title)) {}

  // Adds a figure (its SVG is copied now) to be written as `file_name`: a
  // plain name ending in ".svg", without directory (else Error); names must
  // be unique (else Error).
  void add(const Figure& figure, const std::string& file_name, const std::string& caption);
  // Adds a paragraph of text between figures.
  void add_text(const std::string& text);

  // Number of figures added.
  std::size_t nb_figures() const;
  // The index page alone.
  std::string index() const;
  // Writes the SVG files and index.html into `directory` (created if needed).
  void save(const std::string& directory) const;

 private:
  struct Item {
    std::string file, caption, svg;  // file empty: a paragraph (caption)
  };
  std::string title_;
  std::vector<Item> items_;
};

}  // namespace sillage
