#pragma once
// A small XML reader for the figure tests: it validates our SVG output
// (balanced tags, quoted attributes, known entities only; a test failure
// otherwise) and lists its elements, to count shapes by tag and class.
#include <gtest/gtest.h>

#include <cctype>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace sillage::test {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
};

// Parses an XML text well enough to validate our output: balanced tags,
// quoted attributes, no raw '<' or '&' in text. Fails the test otherwise.
inline std::vector<Element> parse_xml(const std::string& s) {
  std::vector<Element> all;
  std::vector<std::string> open;
  std::size_t i = 0;
  auto fail = [&](const std::string& why) {
    ADD_FAILURE() << why << " at offset " << i << ": " << s.substr(i, 60);
    i = s.size();
  };
  while (i < s.size()) {
    if (s[i] != '<') {
      if (s[i] == '&') {
        const auto semi = s.find(';', i);
        const std::string ent = s.substr(i, semi - i + 1);
        if (ent != "&amp;" && ent != "&lt;" && ent != "&gt;" && ent != "&quot;" && ent != "&apos;") {
          fail("bad entity");
        }
      }
      ++i;
      continue;
    }
    if (s.compare(i, 5, "<?xml") == 0 || s.compare(i, 9, "<!DOCTYPE") == 0) {
      i = s.find('>', i) + 1;
      continue;
    }
    if (s.compare(i, 2, "</") == 0) {
      const auto end = s.find('>', i);
      const std::string name = s.substr(i + 2, end - i - 2);
      if (open.empty() || open.back() != name) return fail("unbalanced </" + name + ">"), all;
      open.pop_back();
      i = end + 1;
      continue;
    }
    ++i;
    Element e;
    while (i < s.size() && std::isalnum(static_cast<unsigned char>(s[i]))) e.name += s[i++];
    if (e.name.empty()) return fail("empty tag name"), all;
    for (;;) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (s.compare(i, 2, "/>") == 0) {
        i += 2;
        break;
      }
      if (i < s.size() && s[i] == '>') {
        ++i;
        open.push_back(e.name);
        break;
      }
      std::string key;
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '-' || s[i] == ':')) {
        key += s[i++];
      }
      if (key.empty() || s[i] != '=' || s[i + 1] != '"') return fail("bad attribute"), all;
      const auto close = s.find('"', i + 2);
      const std::string value = s.substr(i + 2, close - i - 2);
      if (value.find('<') != std::string::npos) return fail("'<' in an attribute"), all;
      if (e.attributes.count(key)) return fail("duplicate attribute " + key), all;
      e.attributes[key] = value;
      i = close + 1;
    }
    all.push_back(e);
  }
  EXPECT_TRUE(open.empty()) << "unclosed <" << (open.empty() ? "" : open.back()) << ">";
  return all;
}

inline std::size_t count(const std::vector<Element>& els, const std::string& name, const std::string& cls = "") {
  std::size_t n = 0;
  for (const auto& e : els) {
    if (e.name != name) continue;
    if (!cls.empty() && (!e.attributes.count("class") || e.attributes.at("class") != cls)) continue;
    ++n;
  }
  return n;
}

}  // namespace sillage::test
