#include "sillage/figures/html.h"

#include <filesystem>
#include <fstream>

namespace sillage {

namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path);
  if (!f) throw Error("Html::save: cannot open '" + path.string() + "' for writing");
  f << text;
  if (!f) throw Error("Html::save: cannot write '" + path.string() + "'");
}

}  // namespace

void Html::add(const Figure& figure, const std::string& file_name, const std::string& caption) {
  const bool plain = !file_name.empty() && file_name.find_first_of("/\\") == std::string::npos &&
                     file_name.size() > 4 && file_name.compare(file_name.size() - 4, 4, ".svg") == 0 &&
                     file_name[0] != '.';
  if (!plain) {
    throw Error("Html::add: '" + file_name + "' must be a plain file name ending in .svg (no directory)");
  }
  for (const auto& it : items_) {
    if (it.file == file_name) throw Error("Html::add: the file name '" + file_name + "' is already used");
  }
  items_.push_back({file_name, caption, figure.svg()});
}

void Html::add_text(const std::string& text) { items_.push_back({"", text, ""}); }

std::size_t Html::nb_figures() const {
  std::size_t n = 0;
  for (const auto& it : items_) n += !it.file.empty();
  return n;
}

std::string Html::index() const {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>" +
                  xml_escape(title_) +
                  "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:auto}"
                  "figure{display:inline-block;margin:1em;vertical-align:top}"
                  "figcaption{max-width:640px;font-size:90%}</style>\n</head>\n<body>\n<h1>" +
                  xml_escape(title_) + "</h1>\n";
  std::size_t k = 0;
  for (const auto& it : items_) {
    if (it.file.empty()) {
      h += "<p>" + xml_escape(it.caption) + "</p>\n";
      continue;
    }
    ++k;
    h += "<figure><img src=\"" + xml_escape(it.file) + "\" alt=\"" + xml_escape(it.caption) +
         "\"/><figcaption>Figure " + std::to_string(k) + ": " + xml_escape(it.caption) + "</figcaption></figure>\n";
  }
  return h + "</body>\n</html>\n";
}

void Html::save(const std::string& directory) const {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec) throw Error("Html::save: cannot create the directory '" + directory + "': " + ec.message());
  const std::filesystem::path dir(directory);
  for (const auto& it : items_) {
    if (!it.file.empty()) write_file(dir / it.file, it.svg);
  }
  write_file(dir / "index.html", index());
}

}  // namespace sillage
