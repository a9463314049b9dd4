#include "yaml_text_mutator.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace dream::testing {
namespace {

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string Joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

size_t Indentation(const std::string& line) {
  return line.find_first_not_of(' ') == std::string::npos ? 0 : line.find_first_not_of(' ');
}

// Where a line's value starts ("key: VALUE", "- VALUE"), or npos.
size_t ValueStart(const std::string& line) {
  const size_t colon = line.find(": ");
  if (colon != std::string::npos && line.find('#') > colon) return colon + 2;
  const size_t indent = Indentation(line);
  if (line.compare(indent, 2, "- ") == 0) return indent + 2;
  return std::string::npos;
}

// Values that a reader of numbers, flags, text and lists must refuse or take.
const std::vector<std::string>& HostileScalars() {
  static const std::vector<std::string> scalars = {"0",
                                                   "-1",
                                                   "-0.0",
                                                   "1e308",
                                                   "-1e308",
                                                   "1e309",
                                                   "4.9e-324",
                                                   "1e-320",
                                                   ".inf",
                                                   "-.inf",
                                                   ".nan",
                                                   "nan",
                                                   "2147483647",
                                                   "2147483648",
                                                   "-2147483649",
                                                   "9223372036854775807",
                                                   "9223372036854775808",
                                                   "-9223372036854775809",
                                                   "18446744073709551616",
                                                   "0x7fffffff",
                                                   "0o17",
                                                   "0b101",
                                                   "1_000",
                                                   "+5",
                                                   "51",
                                                   "1000000",
                                                   "1.5.5",
                                                   "1e",
                                                   "~",
                                                   "null",
                                                   "",
                                                   "true",
                                                   "no",
                                                   "''",
                                                   "\"\"",
                                                   "[]",
                                                   "{}",
                                                   "[1, 2, 3]",
                                                   "{a: 1}",
                                                   "[[1, 2], [3]]",
                                                   "[1e309, -1e309]",
                                                   "[.nan, .nan, .nan]",
                                                   "!!binary aGVsbG8=",
                                                   "!!str 5",
                                                   "!!int 5.5",
                                                   "!!float x",
                                                   "!custom 1",
                                                   "*undefined",
                                                   "&anchor 3",
                                                   "'unterminated",
                                                   "\"unterminated",
                                                   "a: b: c",
                                                   "- x",
                                                   "? x",
                                                   "|",
                                                   ">-",
                                                   "@",
                                                   "`",
                                                   "%",
                                                   "\"\\x00\"",
                                                   "\"\\uFFFF\""};
  return scalars;
}

}  // namespace

std::string YamlTextMutator::Nested(int depth, bool flow) {
  if (flow) return std::string(static_cast<size_t>(depth), '[') + "1" + std::string(static_cast<size_t>(depth), ']');
  std::string text;
  for (int i = 0; i < depth; ++i) text += "\n" + std::string(static_cast<size_t>(2 * (i + 1)), ' ') + "k:";
  return text + " 1";
}

std::string YamlTextMutator::Mutate(const std::string& text) {
  std::vector<std::string> lines = Lines(text);
  const int rounds = Below(3) + 1;
  for (int i = 0; i < rounds; ++i) MutateOnce(&lines);
  return Joined(lines);
}

int YamlTextMutator::LineWithValue(const std::vector<std::string>& lines) {
  std::vector<int> candidates;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (ValueStart(lines[i]) != std::string::npos) candidates.push_back(static_cast<int>(i));
  }
  return candidates.empty() ? -1 : candidates[static_cast<size_t>(Below(candidates.size()))];
}

std::string YamlTextMutator::HostileScalar() {
  const std::vector<std::string>& scalars = HostileScalars();
  return scalars[static_cast<size_t>(Below(scalars.size()))];
}

std::string YamlTextMutator::ScaledNumber(const std::string& number) {
  static const char* const kExponents[] = {"e-320", "e-10", "e3", "e10", "e308", "e400"};
  switch (Below(6)) {
    case 0:
      return number.find_first_of("eE") == std::string::npos ? number + kExponents[Below(std::size(kExponents))]
                                                             : number + "0";
    case 1:
      return number[0] == '-' ? number.substr(1) : "-" + number;
    case 2:
      return number + std::string(static_cast<size_t>(Below(20) + 1), '9');
    case 3:
      return "0." + number;
    case 4:
      return number + ".5";
    default:
      return HostileScalar();
  }
}

void YamlTextMutator::MutateOnce(std::vector<std::string>* lines_pointer) {
  std::vector<std::string>& lines = *lines_pointer;
  if (lines.empty()) lines.emplace_back();
  const auto any_line = [&] { return static_cast<size_t>(Below(lines.size())); };
  switch (Below(13)) {
    case 0: {  // a hostile value
      const int line = LineWithValue(lines);
      if (line >= 0)
        lines[static_cast<size_t>(line)].replace(ValueStart(lines[static_cast<size_t>(line)]), std::string::npos,
                                                 HostileScalar());
      break;
    }
    case 1: {  // a number scaled, negated, lengthened
      static const std::regex kNumber(R"(-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)");
      std::string& line = lines[any_line()];
      std::vector<std::smatch> numbers;
      for (auto it = std::sregex_iterator(line.begin(), line.end(), kNumber); it != std::sregex_iterator(); ++it)
        numbers.push_back(*it);
      if (numbers.empty()) break;
      const std::smatch& chosen = numbers[static_cast<size_t>(Below(numbers.size()))];
      const auto at = static_cast<size_t>(chosen.position(0));
      const auto length = static_cast<size_t>(chosen.length(0));
      line.replace(at, length, ScaledNumber(chosen.str(0)));
      break;
    }
    case 2:  // a line lost
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(any_line()));
      break;
    case 3: {  // a line given twice: a duplicate key, an extra list item
      const size_t line = any_line();
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(Below(2) == 0 ? line + 1 : any_line()), lines[line]);
      break;
    }
    case 4:
      std::swap(lines[any_line()], lines[any_line()]);
      break;
    case 5: {  // indentation off by one, two, four, or a tab
      std::string& line = lines[any_line()];
      switch (Below(4)) {
        case 0:
          line.insert(0, std::string(static_cast<size_t>(1 << Below(3)), ' '));
          break;
        case 1:
          line.erase(0, std::min(Indentation(line), static_cast<size_t>(1 << Below(3))));
          break;
        case 2:
          line.insert(0, "\t");
          break;
        default:
          line = std::string(Indentation(line) / 2, '\t') + line.substr(Indentation(line));
          break;
      }
      break;
    }
    case 6: {  // document and directive markers, complex keys, tags
      static const char* const kMarkers[] = {
          "---",   "...",   "%YAML 1.2", "%TAG ! tag:x,2000:", "--- !!map", "? complex", ": value",
          "!!set", "--- |", "&top"};
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(any_line()), kMarkers[Below(std::size(kMarkers))]);
      break;
    }
    case 7: {  // anchors and aliases: reused, self-containing, exploding, undefined
      const int line = LineWithValue(lines);
      switch (Below(4)) {
        case 0: {
          const int other = LineWithValue(lines);
          if (line < 0 || other < 0) break;
          std::string& anchored = lines[static_cast<size_t>(line)];
          anchored.insert(ValueStart(anchored), "&a ");
          std::string& alias = lines[static_cast<size_t>(other)];
          alias.replace(ValueStart(alias), std::string::npos, "*a");
          break;
        }
        case 1:
          if (line >= 0)
            lines[static_cast<size_t>(line)].replace(ValueStart(lines[static_cast<size_t>(line)]), std::string::npos,
                                                     "&s {x: *s}");
          break;
        case 2: {
          std::vector<std::string> laughs = {"lol0: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]"};
          for (int level = 1; level < 9; ++level) {
            std::string row = "lol" + std::to_string(level) + ": &l" + std::to_string(level) + " [";
            for (int i = 0; i < 10; ++i) row += (i ? ", *l" : "*l") + std::to_string(level - 1);
            laughs.push_back(row + "]");
          }
          lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(Below(2) == 0 ? 0 : lines.size()), laughs.begin(),
                       laughs.end());
          break;
        }
        default:
          if (line >= 0)
            lines[static_cast<size_t>(line)].replace(ValueStart(lines[static_cast<size_t>(line)]), std::string::npos,
                                                     "*nowhere");
          break;
      }
      break;
    }
    case 8: {  // deep nesting, around every limit (ours 100, yaml-cpp's 2000)
      static const int kDepths[] = {2, 10, 99, 100, 101, 1000, 1999, 2000, 2001, 5000};
      const int depth = kDepths[Below(std::size(kDepths))];
      const int line = LineWithValue(lines);
      if (line >= 0 && (depth <= 300 ? Below(2) == 0 : true)) {
        lines[static_cast<size_t>(line)].replace(ValueStart(lines[static_cast<size_t>(line)]), std::string::npos,
                                                 Nested(depth, true));
      } else if (depth <= 300) {
        lines.push_back("deep:" + Nested(depth, false));
      }
      break;
    }
    case 9: {  // a byte an editor or a transfer could leave
      static const char kBytes[] = {'\0', '\t', '\v', '\x1b', '\x7f', '\x80', '\xc3', '\xff', '\xfe',
                                    '\r', '"',  '\'', '{',    '[',    ']',    ':',    '#',    '&',
                                    '*',  '!',  '|',  '>',    '%',    '-',    ','};
      std::string& line = lines[any_line()];
      line.insert(static_cast<size_t>(Below(line.size() + 1)), 1, kBytes[Below(sizeof(kBytes))]);
      break;
    }
    case 10: {  // a file cut short
      std::string text = Joined(lines);
      text.resize(static_cast<size_t>(Below(text.size() + 1)));
      lines = Lines(text);
      break;
    }
    case 11: {  // something very long: a value, a key, a list
      const int line = LineWithValue(lines);
      if (line < 0) break;
      std::string& target = lines[static_cast<size_t>(line)];
      switch (Below(3)) {
        case 0:
          target.replace(ValueStart(target), std::string::npos, std::string(20000, 'x'));
          break;
        case 1:
          target = std::string(Indentation(target), ' ') + std::string(2000, 'k') + ": 1";
          break;
        default: {
          std::string list = "[";
          for (int i = 0; i < 2000; ++i) list += (i ? ", " : "") + std::to_string(i % 7);
          target.replace(ValueStart(target), std::string::npos, list + "]");
          break;
        }
      }
      break;
    }
    default: {  // a key misspelt
      std::string& line = lines[any_line()];
      const size_t colon = line.find(':');
      if (colon == std::string::npos || colon == 0) break;
      if (Below(2) == 0)
        line.erase(static_cast<size_t>(Below(colon)), 1);
      else
        line.insert(colon, "_x");
      break;
    }
  }
}

}  // namespace dream::testing
