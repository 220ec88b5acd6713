#pragma once
// The validators of the deck's parameters (Teuchos), in one place for every
// package that declares parameters: number ranges and string choices. The
// deck checker (io/Deck.cpp) turns their bounds into its messages.
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <initializer_list>
#include <string>
#include <vector>

namespace cgcm::validators {

/// A double ≥ min.
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<double>> atLeast(double min) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>());
  v->setMin(min);
  return v;
}

/// A double in [min, max].
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<double>> between(double min, double max) {
  return Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(min, max));
}

/// An int ≥ min.
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<int>> intAtLeast(int min) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>());
  v->setMin(min);
  return v;
}

/// An int in [min, max].
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<int>> intBetween(int min, int max) {
  return Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(min, max));
}

/// One of the given strings.
inline Teuchos::RCP<Teuchos::StringValidator> choices(std::initializer_list<std::string> names) {
  return Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(names)));
}
inline Teuchos::RCP<Teuchos::StringValidator> choices(const std::vector<std::string>& names) {
  return Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(names.begin(), names.end())));
}

}  // namespace cgcm::validators
