#include "studies/suggest.h"

#include <algorithm>
#include <cctype>

namespace camopt::studies {

namespace {

// Optimal string alignment distance (Damerau–Levenshtein without repeated edits of a substring).
size_t Distance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1, 0));
  for (size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t.");
  return s.substr(b, e - b + 1);
}

}  // namespace

std::string NearestName(const std::string& word, const std::vector<std::string>& candidates) {
  if (word.empty() || word.size() > 200) return "";
  const std::string w = Lower(word);
  size_t best = std::string::npos;
  std::string name;
  bool unique = false;
  for (const std::string& c : candidates) {
    if (c.empty() || c.size() > 200) continue;
    const size_t d = Distance(w, Lower(c));
    if (d == 0) return "";  // not misspelt
    if (d > std::max<size_t>(1, std::max(w.size(), c.size()) / 3)) continue;
    if (d < best) {
      best = d;
      name = c;
      unique = true;
    } else if (d == best && c != name) {
      unique = false;
    }
  }
  return unique ? name : "";
}

std::vector<std::string> NamesInExpected(const std::string& expected) {
  std::vector<std::string> names;
  if (expected.find('"') != std::string::npos) {
    for (size_t open = expected.find('"'); open != std::string::npos;) {
      const size_t close = expected.find('"', open + 1);
      if (close == std::string::npos) break;
      names.push_back(expected.substr(open + 1, close - open - 1));
      open = expected.find('"', close + 1);
    }
    return names;
  }
  std::string list;
  if (expected.rfind("one of ", 0) == 0) {
    list = expected.substr(7);
  } else if (const size_t open = expected.find('('); open != std::string::npos) {
    const size_t close = expected.find(')', open);
    if (close == std::string::npos) return names;
    list = expected.substr(open + 1, close - open - 1);
  } else {
    return names;
  }
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    std::string name = Trim(list.substr(start, comma - start));
    if (name.rfind("or ", 0) == 0) name = Trim(name.substr(3));
    if (!name.empty() && name.find(' ') == std::string::npos) names.push_back(name);
    start = comma + 1;
  }
  return names;
}

}  // namespace camopt::studies
