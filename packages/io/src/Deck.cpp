#include "cgcm/io/Deck.hpp"

#include <cstdlib>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::io {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// Teuchos' exception texts carry the source file, the throw count and the
// failed test before the message: keep the message, on one line.
std::string teuchosMessage(const std::string& what) {
  std::string out, line;
  for (std::istringstream in(what); std::getline(in, line);) {
    line = trim(line);
    if (line.empty() || line.rfind("Throw number", 0) == 0 || line.rfind("Throw test", 0) == 0 ||
        line.find_first_not_of('-') == std::string::npos ||
        (line.back() == ':' && (line.find(".cpp:") != std::string::npos || line.find(".hpp:") != std::string::npos)))
      continue;
    out += (out.empty() ? "" : " ") + line;
  }
  return out.empty() ? trim(what) : out;
}

long parseInteger(const std::string& path, const std::string& text) {
  char* end = nullptr;
  const std::string t = trim(text);
  const long v = std::strtol(t.c_str(), &end, 10);
  if (t.empty() || *end != '\0') throw InputError(path + ": \"" + text + "\" is not an integer");
  return v;
}

// Teuchos reads type="double" value="abc" as 0 without a word: every number of
// the XML file is parsed again here, strictly, with its parameter's path.
void checkXmlNumbers(const Teuchos::XMLObject& node, const std::string& prefix) {
  for (int i = 0; i < node.numChildren(); ++i) {
    const Teuchos::XMLObject& child = node.getChild(i);
    if (!child.hasAttribute("name")) continue;
    const std::string path = prefix + child.getAttribute("name");
    if (child.getTag() == "ParameterList") {
      checkXmlNumbers(child, path + "/");
      continue;
    }
    if (child.getTag() != "Parameter")
      throw InputError(path + ": <" + child.getTag() + "> is not an element of a deck; use <Parameter> or <ParameterList>");
    if (!child.hasAttribute("type") || !child.hasAttribute("value"))
      throw InputError(path + ": a <Parameter> needs name, type and value attributes");
    const std::string type = child.getAttribute("type"), value = child.getAttribute("value");
    static const char* known[] = {"double", "int", "bool", "string", "Array(double)", "Array(int)", "Array(string)"};
    if (std::find(std::begin(known), std::end(known), type) == std::end(known))
      throw InputError(path + ": type \"" + type + "\" is not one a deck uses; allowed: double, int, bool, string, "
                       "Array(double), Array(int), Array(string)");
    if (type == "double") parseDouble(path, value);
    if (type == "int") parseInteger(path, value);
    if (type == "bool") {
      std::string b = trim(value);
      for (char& c : b) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (b != "true" && b != "false" && b != "1" && b != "0")
        throw InputError(path + ": \"" + value + "\" is not true or false");
    }
    if (type == "Array(string)") {
      const std::string t = trim(value);
      if (t.size() < 2 || t.front() != '{' || t.back() != '}')
        throw InputError(path + ": \"" + value + "\" is not an array; write {a, b, c}");
    }
    if (type == "Array(double)" || type == "Array(int)") {
      const std::string t = trim(value);
      if (t.size() < 2 || t.front() != '{' || t.back() != '}')
        throw InputError(path + ": \"" + value + "\" is not an array; write {a, b, c}");
      const auto open = value.find('{'), close = value.rfind('}');
      std::stringstream items(value.substr(open + 1, close - open - 1));
      for (std::string item; std::getline(items, item, ',');)
        if (!trim(item).empty()) type == "Array(double)" ? void(parseDouble(path, item)) : void(parseInteger(path, item));
    }
  }
}

template <class T>
std::string numberText(T v) {
  std::ostringstream os;
  os.precision(12);
  os << v;
  return os.str();
}

// A value outside its validator's range or choices, in one line: "<path> = <value>: <why>; allowed: ...".
void checkRange(const Teuchos::ParameterEntry& e, const Teuchos::ParameterEntry& v, const std::string& path) {
  if (v.validator().is_null()) return;
  const std::string doc = v.docString().empty() ? "" : " (" + v.docString() + ")";
  auto bounds = [&](auto value, const auto& validator) {
    const bool low = validator->hasMin() && value < validator->getMin();
    const bool high = validator->hasMax() && value > validator->getMax();
    if (!low && !high) return;
    std::string allowed = validator->hasMin() ? numberText(validator->getMin()) : "";
    allowed += validator->hasMax() ? " .. " + numberText(validator->getMax()) : " or more";
    throw InputError(path + " = " + numberText(value) + ": out of range; allowed: " + allowed + doc);
  };
  if (e.isType<double>())
    if (auto d = Teuchos::rcp_dynamic_cast<const Teuchos::EnhancedNumberValidator<double>>(v.validator()); !d.is_null())
      bounds(e.getValue<double>(nullptr), d);
  if (e.isType<int>())
    if (auto d = Teuchos::rcp_dynamic_cast<const Teuchos::EnhancedNumberValidator<int>>(v.validator()); !d.is_null())
      bounds(e.getValue<int>(nullptr), d);
  if (e.isType<std::string>())
    if (auto d = Teuchos::rcp_dynamic_cast<const Teuchos::StringValidator>(v.validator()); !d.is_null()) {
      const auto& choices = *d->validStringValues();
      const std::string value = e.getValue<std::string>(nullptr);
      if (std::find(choices.begin(), choices.end(), value) != choices.end()) return;
      std::string allowed;
      for (const auto& c : choices) allowed += (allowed.empty() ? "\"" : ", \"") + c + "\"";
      throw InputError(path + " = \"" + value + "\": not a choice; allowed: " + allowed);
    }
}

// Numbers given as text (type="string" value="2.5") where a number is expected
// become numbers, or an InputError naming the parameter; doubles (and arrays
// of doubles) must be finite.
void normaliseNumbers(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& prefix) {
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string name = deck.name(it), path = prefix + name;
    if (!valid.isParameter(name)) continue;  // Teuchos names unknown parameters
    const auto& v = valid.getEntry(name);
    auto& e = deck.getEntry(name);
    if (deck.isSublist(name)) {
      if (valid.isSublist(name)) normaliseNumbers(deck.sublist(name), valid.sublist(name), path + "/");
      continue;
    }
    if (v.isType<double>() && e.isType<std::string>()) e.setValue(parseDouble(path, e.getValue<std::string>(nullptr)));
    if (v.isType<double>() && e.isType<int>()) e.setValue(double(e.getValue<int>(nullptr)));
    if (v.isType<int>() && e.isType<std::string>()) e.setValue(int(parseInteger(path, e.getValue<std::string>(nullptr))));
    checkRange(e, v, path);
  }
}

// Lists the names of a sublist's entries, for error messages.
std::string entryNames(const Teuchos::ParameterList& list) {
  std::string names;
  for (auto it = list.begin(); it != list.end(); ++it)
    names += (names.empty() ? "" : ", ") + ("\"" + list.name(it) + "\"");
  return names;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// "<path>: unknown parameter (did you mean "<nearest>"?); allowed in <group>: ..."
InputError unknownName(const std::string& path, const std::string& name, const Teuchos::ParameterList& valid,
                       const std::string& prefix, bool group) {
  const std::string where = prefix.empty() ? "at the top of the deck" : "in " + prefix.substr(0, prefix.size() - 1);
  std::string nearest;
  std::size_t best = 3;
  for (auto v = valid.begin(); v != valid.end(); ++v)
    if (const std::size_t d = editDistance(name, valid.name(v)); d < best) best = d, nearest = valid.name(v);
  return InputError(path + ": unknown " + (group ? "parameter group" : "parameter") +
                    (nearest.empty() ? "" : " (did you mean \"" + nearest + "\"?)") + "; allowed " + where + ": " +
                    entryNames(valid));
}

// Unknown names (with the nearest valid one), and a value where a group of
// parameters belongs or the reverse. Groups handed to a library as they are
// (LOCA, Stratimikos: no valid entries of their own) are left to it.
void checkNamesAndKinds(const Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid,
                        const std::string& prefix) {
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string name = deck.name(it), path = prefix + name;
    const bool group = deck.isSublist(name);
    if (!valid.isParameter(name)) throw unknownName(path, name, valid, prefix, group);
    if (valid.isSublist(name) && !group)
      throw InputError(path + ": a group of parameters (<ParameterList name=\"" + name + "\">) belongs here, not a value");
    if (!valid.isSublist(name) && group)
      throw InputError(path + ": a single <Parameter> belongs here, not a group of parameters");
    if (group && valid.sublist(name).numParams() > 0) checkNamesAndKinds(deck.sublist(name), valid.sublist(name), path + "/");
  }
}

std::string typeName(const Teuchos::ParameterEntry& e) {
  if (e.isType<double>()) return "double";
  if (e.isType<int>()) return "int";
  if (e.isType<bool>()) return "bool";
  if (e.isType<std::string>()) return "string";
  if (e.isType<Teuchos::Array<double>>()) return "Array(double)";
  if (e.isType<Teuchos::Array<int>>()) return "Array(int)";
  if (e.isType<Teuchos::Array<std::string>>()) return "Array(string)";
  return e.getAny().typeName();
}

// After normaliseNumbers: every value of the type its parameter has.
void checkTypes(const Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& prefix) {
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string name = deck.name(it), path = prefix + name;
    if (deck.isSublist(name)) {
      if (valid.sublist(name).numParams() > 0) checkTypes(deck.sublist(name), valid.sublist(name), path + "/");
      continue;
    }
    const auto& e = deck.getEntry(name);
    const auto& v = valid.getEntry(name);
    if (e.getAny().type() != v.getAny().type())
      throw InputError(path + ": given as " + typeName(e) + ", expected " + typeName(v) +
                       (v.isType<Teuchos::Array<double>>() ? " (e.g. value=\"{-0.02, 0.06}\")" : ""));
  }
}

}  // namespace

double parseDouble(const std::string& path, const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || trim(text.substr(used)) != "")
    throw InputError(path + ": \"" + text + "\" is not a number");
  if (!std::isfinite(v)) throw InputError(path + ": \"" + trim(text) + "\" is not a finite number");
  return v;
}

int xmlNestingDepth(const std::string& text, int stopAbove) {
  const std::size_t n = text.size();
  // the position after the first `close` at or after `from` (n if none)
  auto past = [&](std::size_t from, const char* close) {
    const auto at = text.find(close, from);
    return at == std::string::npos ? n : at + std::strlen(close);
  };
  int depth = 0, deepest = 0;
  for (std::size_t i = text.find('<'); i < n; i = text.find('<', i)) {
    if (text.compare(i, 4, "<!--") == 0) {
      i = past(i + 4, "-->");
    } else if (text.compare(i, 9, "<![CDATA[") == 0) {
      i = past(i + 9, "]]>");
    } else if (text.compare(i, 2, "<?") == 0) {
      i = past(i + 2, "?>");
    } else if (text.compare(i, 2, "<!") == 0) {  // <!DOCTYPE ...>, with an internal subset in [...]
      int brackets = 0;
      char quote = 0;
      for (i += 2; i < n; ++i) {
        const char c = text[i];
        if (quote) {
          if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '[') {
          ++brackets;
        } else if (c == ']') {
          --brackets;
        } else if (c == '>' && brackets <= 0) {
          break;
        }
      }
      ++i;
    } else if (text.compare(i, 2, "</") == 0) {
      depth = std::max(0, depth - 1);
      i = past(i + 2, ">");
    } else {  // a start tag: to its '>' outside quoted attribute values
      char quote = 0;
      std::size_t j = i + 1;
      for (; j < n; ++j) {
        const char c = text[j];
        if (quote) {
          if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '>') {
          break;
        }
      }
      if (j >= n) break;  // unterminated: the parser's to report
      if (text[j - 1] != '/') {
        deepest = std::max(deepest, ++depth);
        if (deepest > stopAbove) return stopAbove + 1;
      }
      i = j + 1;
    }
  }
  return deepest;
}

Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path) {
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError("cannot read the input deck \"" + path + "\"");
  const std::string text{std::istreambuf_iterator<char>(probe), std::istreambuf_iterator<char>()};
  if (xmlNestingDepth(text, kMaxDeckNesting) > kMaxDeckNesting)
    throw InputError("input deck \"" + path + "\" nests its elements more than " + std::to_string(kMaxDeckNesting) +
                     " levels deep (the limit; a deck needs 3 or 4): refused before parsing");
  // The XML and every value are checked here, with the parameter's path,
  // before Teuchos converts them (it reads a bad number as 0).
  Teuchos::XMLObject xml;
  try {
    xml = Teuchos::FileInputSource(path).getObject();
  } catch (const std::exception& e) {
    throw InputError("input deck \"" + path + "\" is not valid XML: " + teuchosMessage(e.what()));
  }
  if (xml.getTag() != "ParameterList")
    throw InputError("input deck \"" + path + "\": the outer element is <" + xml.getTag() + ">, not <ParameterList>");
  checkXmlNumbers(xml, "");
  Teuchos::RCP<Teuchos::ParameterList> deck;
  try {
    deck = Teuchos::getParametersFromXmlFile(path);
  } catch (const std::exception& e) {
    throw InputError("input deck \"" + path + "\" is not a valid parameter list: " + teuchosMessage(e.what()));
  }
  return deck;
}

void applyOverrides(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid,
                    const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("command-line argument \"" + o + "\" is not of the form Path/To/Parameter=value");
    const std::string path = trim(o.substr(0, eq)), text = trim(o.substr(eq + 1));
    std::vector<std::string> parts;
    std::stringstream ss(path);
    for (std::string part; std::getline(ss, part, '/');) parts.push_back(part);
    const Teuchos::ParameterList* v = &valid;
    Teuchos::ParameterList* d = &deck;
    std::string prefix;
    bool passThrough = false;  // a sublist handed to a library as it is (LOCA, Stratimikos)
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (passThrough || (v->isSublist(parts[i]) && v->sublist(parts[i]).numParams() == 0)) {
        passThrough = true;
        d = &d->sublist(parts[i]);
        prefix += parts[i] + "/";
        continue;
      }
      if (!v->isParameter(parts[i])) throw unknownName(prefix + parts[i], parts[i], *v, prefix, true);
      if (!v->isSublist(parts[i]))
        throw InputError(prefix + parts[i] + ": a single parameter, not a group (in the override " + path + ")");
      v = &v->sublist(parts[i]);
      d = &d->sublist(parts[i]);
      prefix += parts[i] + "/";
    }
    const std::string& name = parts.back();
    if (passThrough) {
      // Typed as the deck has it, or from the text: true/false, an integer, a
      // number with a point or an exponent (a double), else a string.
      const bool hasEntry = d->isParameter(name) && !d->isSublist(name);
      char* end = nullptr;
      const long asInt = std::strtol(text.c_str(), &end, 10);
      const bool isInt = !text.empty() && *end == '\0';
      std::strtod(text.c_str(), &end);
      const bool isNumber = !text.empty() && *end == '\0';
      if ((hasEntry && d->getEntry(name).isType<bool>()) || (!hasEntry && (text == "true" || text == "false")))
        d->set(name, text == "true" || text == "1");
      else if ((hasEntry && d->getEntry(name).isType<int>()) || (!hasEntry && isInt))
        d->set(name, int(asInt));
      else if ((hasEntry && d->getEntry(name).isType<double>()) || (!hasEntry && isNumber))
        d->set(name, parseDouble(path, text));
      else
        d->set(name, text);
      continue;
    }
    if (!v->isParameter(name)) throw unknownName(path, name, *v, prefix, false);
    if (v->isSublist(name))
      throw InputError(path + ": a group of parameters; give one of its parameters, e.g. " + path + "/" +
                       (v->sublist(name).numParams() > 0 ? v->sublist(name).name(v->sublist(name).begin()) : "name") +
                       "=value");
    const Teuchos::ParameterEntry& entry = v->getEntry(name);
    if (entry.isType<double>()) {
      d->set(name, parseDouble(path, text));
    } else if (entry.isType<int>()) {
      d->set(name, int(parseInteger(path, text)));
    } else if (entry.isType<bool>()) {
      if (text == "true" || text == "1") d->set(name, true);
      else if (text == "false" || text == "0") d->set(name, false);
      else throw InputError(path + ": \"" + text + "\" is not true or false");
    } else if (entry.isType<std::string>()) {
      d->set(name, text);
    } else if (entry.isType<Teuchos::Array<double>>()) {
      std::string body = text;
      if (!body.empty() && body.front() == '{') body = body.substr(1);
      if (!body.empty() && body.back() == '}') body.pop_back();
      Teuchos::Array<double> values;
      std::stringstream vs(body);
      for (std::string item; std::getline(vs, item, ',');) values.push_back(parseDouble(path, trim(item)));
      d->set(name, values);
    } else {
      throw InputError(path + ": this parameter cannot be set from the command line");
    }
  }
}

void validateDeck(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& prefix) {
  checkNamesAndKinds(deck, valid, prefix);
  normaliseNumbers(deck, valid, prefix);
  checkTypes(deck, valid, prefix);
  try {
    deck.validateParametersAndSetDefaults(valid);
  } catch (const std::exception& e) {
    // what the checks above do not catch: Teuchos' message, on one line
    std::string what = teuchosMessage(e.what());
    for (std::string::size_type at; (at = what.find("ANONYMOUS->")) != std::string::npos;) what.erase(at, 11);
    throw InputError("invalid input deck: " + what);
  }
}

void printHelp(std::ostream& out, const Teuchos::ParameterList& valid) {
  valid.print(out, Teuchos::ParameterList::PrintOptions().showDoc(true).indent(2).showTypes(true));
}

void writeDeck(const Teuchos::ParameterList& deck, const std::string& path) {
  std::ofstream out(path);
  if (out) Teuchos::writeParameterListToXmlOStream(deck, out);
  if (!out || !out.flush()) throw InputError("cannot write \"" + path + "\"");
}

}  // namespace cgcm::io
