#pragma once
// Input decks: Teuchos XML parameter lists, validated against the list of
// every parameter cgcm knows (with defaults and documentation), plus
// command-line overrides "Path/To/Parameter=value".
#include <Teuchos_ParameterList.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace cgcm::io {

/// Reads an XML deck. Throws InputError if the file is missing, nests its
/// elements deeper than kMaxDeckNesting, or is not a parameter list.
Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path);

/// The deepest element nesting readDeck accepts. A deck nests 3 or 4 levels
/// (cgcm > Bodies > tip > parameter; a LOCA or Stratimikos list a few more);
/// 64 leaves room for any hand-written list. The XML tree is walked by
/// recursion (readDeck's number check, Teuchos' parameter-list reader and
/// the tree's destructor), stack frames per level: 10 000 levels ended in a
/// segmentation fault instead of a message, so deeper files are refused
/// before they are parsed.
constexpr int kMaxDeckNesting = 64;

/// The deepest nesting of elements in the XML `text` (0: no element), found
/// by a scan of its tags, without parsing: comments, CDATA sections,
/// processing instructions and <!DOCTYPE ...> are skipped, a self-closing
/// tag <a/> does not nest, and '>' or '<' in a quoted attribute value is
/// text. The scan stops once the depth exceeds `stopAbove` (it then returns
/// stopAbove + 1). Unterminated or unbalanced markup is left to the parser.
int xmlNestingDepth(const std::string& text, int stopAbove = kMaxDeckNesting);

/// Applies overrides of the form "Sublist/Sub/Parameter=value". The value is
/// parsed with the type the valid list gives the parameter (double, int, bool,
/// string, Array(double) as {a, b, c}). Throws InputError naming the path if
/// it is unknown or the value does not parse.
void applyOverrides(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid,
                    const std::vector<std::string>& overrides);

/// The finite number `text` (surrounding blanks allowed, nothing else);
/// throws InputError "<path>: "<text>" is not a number" otherwise, or
/// "... is not a finite number" for inf and nan.
double parseDouble(const std::string& path, const std::string& text);

/// Validates `deck` against `valid` and fills in defaults. Unknown names, wrong
/// types and out-of-range values throw InputError with the full parameter path
/// (`prefix` + the path in `deck`, e.g. "Bodies/tip/" for a sublist checked on
/// its own) and the allowed values.
void validateDeck(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& prefix = "");

/// Prints every parameter with its default, type and documentation.
void printHelp(std::ostream& out, const Teuchos::ParameterList& valid);

/// Writes a parameter list as XML. Throws InputError if the file cannot be written.
void writeDeck(const Teuchos::ParameterList& deck, const std::string& path);

}  // namespace cgcm::io
