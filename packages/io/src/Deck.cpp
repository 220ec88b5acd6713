#include "cgcm/io/Deck.hpp"

#include <cstdlib>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::io {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
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
    if (child.getTag() != "Parameter" || !child.hasAttribute("type") || !child.hasAttribute("value")) continue;
    const std::string type = child.getAttribute("type"), value = child.getAttribute("value");
    if (type == "double") parseDouble(path, value);
    if (type == "int") parseInteger(path, value);
    if (type == "Array(double)" || type == "Array(int)") {
      const auto open = value.find('{'), close = value.rfind('}');
      if (open == std::string::npos || close == std::string::npos || close < open)
        throw InputError(path + ": \"" + value + "\" is not an array; write {a, b, c}");
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

Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw InputError("cannot read the input deck \"" + path + "\"");
  Teuchos::RCP<Teuchos::ParameterList> deck;
  try {
    deck = Teuchos::getParametersFromXmlFile(path);
  } catch (const std::exception& e) {
    throw InputError("input deck \"" + path + "\" is not a valid XML parameter list: " + e.what());
  }
  checkXmlNumbers(Teuchos::FileInputSource(path).getObject(), "");
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
      if (!v->isSublist(parts[i]))
        throw InputError("override " + path + ": \"" + prefix + parts[i] + "\" is not a parameter group; valid at " +
                         (prefix.empty() ? "top level" : prefix) + ": " + entryNames(*v));
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
    if (!v->isParameter(name) || v->isSublist(name))
      throw InputError("override " + path + ": unknown parameter \"" + name + "\"; valid in " +
                       (prefix.empty() ? "top level" : prefix) + ": " + entryNames(*v));
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

void validateDeck(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid) {
  normaliseNumbers(deck, valid, "");
  try {
    deck.validateParametersAndSetDefaults(valid);
  } catch (const Teuchos::Exceptions::InvalidParameter& e) {
    // Teuchos' messages name the parameter, its sublist and the valid choices;
    // drop the source location and throw bookkeeping in front of that.
    std::string what = e.what();
    const auto start = what.find("The \"");
    if (start != std::string::npos) what = what.substr(start);
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
