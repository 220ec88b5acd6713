#pragma once
// The validators of the deck's parameters (Teuchos), in one place for every
// package that declares parameters: number ranges and string choices. The
// deck checker (io/Deck.cpp) turns their bounds into its messages.
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <initializer_list>
#include <string>
#include <vector>

namespace cgcm::validators {

namespace detail {
template <class T>
Teuchos::RCP<Teuchos::EnhancedNumberValidator<T>> minimum(T min) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<T>());
  v->setMin(min);
  return v;
}
}  // namespace detail

// The type is in the name: a validator of the wrong type would refuse every
// value of its parameter, so atLeast(2) must not quietly mean an int.
/// A double ≥ min.
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<double>> atLeast(double min) { return detail::minimum(min); }
/// A double in [min, max].
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<double>> between(double min, double max) {
  return Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(min, max));
}
/// An int ≥ min.
inline Teuchos::RCP<Teuchos::EnhancedNumberValidator<int>> intAtLeast(int min) { return detail::minimum(min); }
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
