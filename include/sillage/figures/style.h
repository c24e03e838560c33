#pragma once
// Drawing styles of figures, and the thesis colour code (Fig. 2.11): green for
// inner boxes, yellow for boundary boxes, blue for boxes proven outside.
#include <string>

#include "sillage/paving/paving_tag.h"

namespace sillage {

struct Style {
  std::string fill = "none";     // any SVG colour: "#8fd18f", "red", "none"
  // SVG stroke colour.
  std::string stroke = "black";
  double stroke_width = 1.0;     // in pixels
  double opacity = 1.0;          // fill opacity, in [0, 1]
  std::string css_class;         // optional class attribute ("inner", ...)
  // Text of the legend entry of what is drawn with this style; none if empty.
  // Initialised so that the older 5-field initialisers stay warning-free.
  std::string label{};
};

// The thesis colours of a paving leaf; css_class is the tag in lower case.
Style paving_style(PavingTag tag);

}  // namespace sillage
