// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Named options declared once, beside the config struct they set: each
// option's name, type, accepted range, one-line help and how a value sets
// the config. Its default is the config struct's own member initialiser,
// printed from a default-constructed config, so it is written in one
// place. A host (a MEX gateway: mex/estimator_args.hpp's
// read_option_table; a C++ program: set_option) reads options through a
// table; the estimator's own validation is the one range check. The tables
// are also what the toolbox's help texts are checked against. Tables:
// recursive/recursive_options.hpp (the recursive estimators),
// offline/output_error_options.hpp (the output-error estimators),
// offline/refined_iv_options.hpp (the offline refined-IV estimators).
#pragma once

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

enum class OptionType {
  kReal,           // a finite real scalar
  kInteger,        // an integer scalar
  kIntegerVector,  // integers, one per input
  kFlag,           // true or false
  kChoice,         // one word of a fixed list
  kMatrix,         // a real matrix (its size is checked by validate())
};

inline const char* option_type_name(OptionType type) {
  switch (type) {
    case OptionType::kReal:
      return "real scalar";
    case OptionType::kInteger:
      return "integer";
    case OptionType::kIntegerVector:
      return "integer vector";
    case OptionType::kFlag:
      return "logical";
    case OptionType::kChoice:
      return "choice";
    case OptionType::kMatrix:
      return "real matrix";
  }
  return "";
}

// One option's value as a host read it: the member of its type.
struct OptionValue {
  double real = 0;
  int integer = 0;
  std::vector<int> integers;
  bool flag = false;
  std::string word;
  Matrix<double> matrix;
};

template <typename Config>
struct OptionDecl {
  const char* name;
  OptionType type;
  bool required;
  std::vector<const char*> choices;  // kChoice: the accepted words
  const char* range;                 // what validate() accepts, in words
  const char* help;                  // one line
  // The option's value in a config, as text (its default for a default
  // config).
  std::function<std::string(const Config&)> show;
  // Sets the config from a value of the declared type (a kChoice value is
  // one of `choices`; the host checks that).
  std::function<Status(Config*, const OptionValue&)> set;
};

template <typename Config>
using OptionTable = std::vector<OptionDecl<Config>>;

namespace options_detail {

inline std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

inline std::string integers(const std::vector<int>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    s += (i ? " " : "") + std::to_string(v[i]);
  }
  return s + "]";
}

template <typename S>
std::string matrix_text(const Matrix<S>& m, const char* empty) {
  if (m.size() == 0) return empty;
  return std::to_string(m.rows()) + "x" + std::to_string(m.cols());
}

// A vector option (th0, the scaling, a polynomial in q^-1) into target;
// a matrix with more than one row and column is an error of kind `code`.
template <typename S>
Status set_vector(const OptionValue& v, const char* what, ErrorCode code,
                  Vector<S>* target) {
  const Matrix<double>& m = v.matrix;
  if (m.rows() > 1 && m.cols() > 1) {
    return Status(code, std::string(what) + " must be a vector");
  }
  *target = Eigen::Map<const Vector<double>>(m.data(), m.size()).cast<S>();
  return Status::Ok();
}

inline const char* intersample_word(InterSample rule) {
  switch (rule) {
    case InterSample::kZoh:
      return "zoh";
    case InterSample::kFoh:
      return "foh";
    case InterSample::kTrapezoid:
      return "trapezoid";
  }
  return "";
}

inline InterSample intersample_of(const std::string& word) {
  if (word == "foh") return InterSample::kFoh;
  if (word == "trapezoid") return InterSample::kTrapezoid;
  return InterSample::kZoh;
}

}  // namespace options_detail

template <typename Config>
const OptionDecl<Config>* find_option(const OptionTable<Config>& table,
                                      const std::string& name) {
  for (const auto& decl : table) {
    if (name == decl.name) return &decl;
  }
  return nullptr;
}

// The option's default: its value in a default-constructed config.
template <typename Config>
std::string option_default(const OptionDecl<Config>& decl) {
  return decl.show(Config{});
}

// The words a kChoice option accepts, for messages: "'a', 'b'".
template <typename Config>
std::string option_choices(const OptionDecl<Config>& decl) {
  std::string allowed;
  for (const char* word : decl.choices) {
    allowed += (allowed.empty() ? "'" : ", '") + std::string(word) + "'";
  }
  return allowed;
}

// Sets the option `decl` declares; a word outside its choices is a bad
// option. The ranges are checked by validate(config) once every option is
// set.
template <typename Config>
Status set_option(const OptionDecl<Config>& decl, const OptionValue& value,
                  Config* config) {
  if (decl.type == OptionType::kChoice) {
    bool known = false;
    for (const char* word : decl.choices) known = known || value.word == word;
    if (!known) {
      return Status(ErrorCode::kBadOption,
                    std::string("option '") + decl.name + "' must be one of " +
                        option_choices(decl) + ", got '" + value.word + "'");
    }
  }
  return decl.set(config, value);
}

// An option of type `type` held in one member of the config: `member`
// returns it for a config (a generic lambda,
// [](auto& c) -> auto& { return c.settings.tolerance; }, which serves the
// const config that shows it and the one a value sets); show(value) is its
// text, set(member, option value) assigns it. The builders below are its
// forms.
template <typename Config, typename Member, typename Show, typename Set>
OptionDecl<Config> member_option(const char* name, OptionType type,
                                 bool required, const char* range,
                                 const char* help, Member member, Show show,
                                 Set set) {
  return {name,
          type,
          required,
          {},
          range,
          help,
          [member, show](const Config& c) { return show(member(c)); },
          [member, set](Config* c, const OptionValue& v) {
            return set(member(*c), v);
          }};
}

// A real (kReal) or integer (kInteger) option held in one member of the
// config (as member_option). The value is assigned as it is; validate() of
// the estimator checks its range.
template <typename Config, typename Member>
OptionDecl<Config> real_option(const char* name, bool required,
                               const char* range, const char* help,
                               Member member) {
  return member_option<Config>(
      name, OptionType::kReal, required, range, help, member,
      [](const auto& x) {
        return options_detail::number(static_cast<double>(x));
      },
      [](auto& target, const OptionValue& v) {
        target = static_cast<std::decay_t<decltype(target)>>(v.real);
        return Status::Ok();
      });
}

// A real (kReal) held in one member, as real_option, whose default NaN
// stands for a value the estimator derives from the data: shown as
// `derived` while it is NaN.
template <typename Config, typename Member>
OptionDecl<Config> derived_real_option(const char* name, const char* range,
                                       const char* help, const char* derived,
                                       Member member) {
  OptionDecl<Config> decl =
      real_option<Config>(name, false, range, help, member);
  decl.show = [member, derived](const Config& c) {
    const double v = static_cast<double>(member(c));
    return std::isnan(v) ? std::string(derived) : options_detail::number(v);
  };
  return decl;
}

template <typename Config, typename Member>
OptionDecl<Config> integer_option(const char* name, bool required,
                                  const char* range, const char* help,
                                  Member member) {
  return member_option<Config>(
      name, OptionType::kInteger, required, range, help, member,
      [](const auto& x) { return std::to_string(x); },
      [](auto& target, const OptionValue& v) {
        target = static_cast<std::decay_t<decltype(target)>>(v.integer);
        return Status::Ok();
      });
}

// Integers one per input, channel or group (kIntegerVector) held in one
// std::vector<int> member, as real_option; shown as [n1 n2 ..].
template <typename Config, typename Member>
OptionDecl<Config> integer_vector_option(const char* name, bool required,
                                         const char* range, const char* help,
                                         Member member) {
  return member_option<Config>(
      name, OptionType::kIntegerVector, required, range, help, member,
      [](const std::vector<int>& x) { return options_detail::integers(x); },
      [](std::vector<int>& target, const OptionValue& v) {
        target = v.integers;
        return Status::Ok();
      });
}

// Reals one per input, channel or parameter (kMatrix, taken in column-major
// order whatever its shape) held in one std::vector member, as
// real_option; shown as `empty` while the list is empty, else by its
// length.
template <typename Config, typename Member>
OptionDecl<Config> real_list_option(const char* name, const char* range,
                                    const char* help, std::string empty,
                                    Member member) {
  return member_option<Config>(
      name, OptionType::kMatrix, false, range, help, member,
      [empty](const auto& list) {
        return list.empty() ? empty : std::to_string(list.size()) + " value(s)";
      },
      [](auto& target, const OptionValue& v) {
        const Matrix<double>& m = v.matrix;
        target.assign(m.data(), m.data() + m.size());
        return Status::Ok();
      });
}

// A flag (kFlag) held in one member, as real_option; shown as true or
// false, `range` the words a host accepts for it.
template <typename Config, typename Member>
OptionDecl<Config> flag_option(const char* name, const char* range,
                               const char* help, Member member) {
  return member_option<Config>(
      name, OptionType::kFlag, false, range, help, member,
      [](bool x) { return std::string(x ? "true" : "false"); },
      [](bool& target, const OptionValue& v) {
        target = v.flag;
        return Status::Ok();
      });
}

// A vector (kMatrix) held in one member, as real_option: a matrix with
// more than one row and column is an error of kind `code`; shown by its
// size, or by `empty` when it is not given.
template <typename Config, typename Member>
OptionDecl<Config> vector_option(const char* name, const char* range,
                                 const char* help, const char* empty,
                                 ErrorCode code, Member member) {
  return member_option<Config>(
      name, OptionType::kMatrix, false, range, help, member,
      [empty](const auto& x) {
        using Scalar = typename std::decay_t<decltype(x)>::Scalar;
        return options_detail::matrix_text(Matrix<Scalar>(x), empty);
      },
      [name, code](auto& target, const OptionValue& v) {
        using Scalar = typename std::decay_t<decltype(target)>::Scalar;
        return options_detail::set_vector<Scalar>(v, name, code, &target);
      });
}

// The accessor of a data member for the builders above:
// member_access(&C::alpha).
template <typename Config, typename T>
auto member_access(T Config::*member) {
  return [member](auto& c) -> auto& { return c.*member; };
}

// The options that several tables declare alike: the structure one entry
// per input of the output-error (offline/output_error_options.hpp) and the
// Box-Jenkins refined-IV (offline/refined_iv_options.hpp, rivc_options)
// estimators.
template <typename Config, typename Member>
OptionDecl<Config> numerator_counts_option(bool required, Member member) {
  return integer_vector_option<Config>(
      "nb", required, ">= 1 each, at most nf + 1",
      "numerator coefficients, one per input", member);
}

template <typename Config, typename Member>
OptionDecl<Config> input_delays_option(Member member) {
  return integer_vector_option<Config>("nk", false, ">= 0 each",
                                       "input delay in samples, one per input",
                                       member);
}

// Sets one option by name; an unknown name is a bad option.
template <typename Config>
Status set_option(const OptionTable<Config>& table, const std::string& name,
                  const OptionValue& value, Config* config) {
  const OptionDecl<Config>* decl = find_option(table, name);
  if (decl == nullptr) {
    return Status(ErrorCode::kBadOption, "unknown option '" + name + "'");
  }
  return set_option(*decl, value, config);
}

}  // namespace ctid
