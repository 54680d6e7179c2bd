// The name-value list of a parameter struct (core/parameter_visitor.hpp): ranges and their
// text, enum choices, and what a visitor sees of a struct's visit(), in order.
#include "core/parameter_visitor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/cosmos_parameters.hpp"

namespace cosmos {
namespace {

enum class Flavour { kSweet, kSour, kBitter };

std::span<const ParameterChoice<Flavour>> parameter_choices(Flavour) {
  static constexpr ParameterChoice<Flavour> kChoices[] = {
      {Flavour::kSweet, "sweet"}, {Flavour::kSour, "sour"}, {Flavour::kBitter, "bitter"}};
  return kChoices;
}

struct Inner {
  int count = 3;
  template <class Visitor>
  void visit(Visitor& v) {
    v("count", count, "how many", Range{1, 9});
  }
};

struct Outer {
  double length_mm = 2.5;
  Flavour flavour = Flavour::kSour;
  Inner inner;
  Inner inlined;
  template <class Visitor>
  void visit(Visitor& v) {
    v("length_mm", length_mm, "a length, mm", Range::above(0, 10));
    v("flavour", flavour, "a flavour");
    v.retired("size_mm", "length_mm");
    v("inner", inner, "a nested map");
    v.fields(inlined);
  }
};

struct NoVisit {
  int x = 0;
};

// Records every call in order: "key|description|range" and the fields' values.
struct Recorder {
  template <class T>
  void operator()(const char* key, T& field, const char* description, const Range& range = {}) {
    calls.push_back(std::string(key) + "|" + description + "|" +
                    (range.bounded() ? range.text() : ""));
    if constexpr (VisitableParameters<T>) {
      visit_parameters(*this, field);
      calls.push_back("end " + std::string(key));
    }
  }
  template <class T>
  void fields(T& nested) {
    calls.push_back("fields");
    visit_parameters(*this, nested);
  }
  void retired(const char* key, const char* replacement) {
    calls.push_back(std::string("retired ") + key + " -> " + replacement);
  }
  std::vector<std::string> calls;
};

TEST(ParameterRange, ContainsHonoursOpenEndsAndRefusesNonFiniteValues) {
  const Range closed{3, 15};
  EXPECT_TRUE(closed.contains(3));
  EXPECT_TRUE(closed.contains(15));
  EXPECT_FALSE(closed.contains(15.0001));
  const Range above = Range::above(0, 100);
  EXPECT_FALSE(above.contains(0));
  EXPECT_TRUE(above.contains(100));
  const Range below = Range::below(0, 1);
  EXPECT_TRUE(below.contains(0));
  EXPECT_FALSE(below.contains(1));
  EXPECT_FALSE(Range::open(0, 1).contains(1));
  const Range any;
  EXPECT_FALSE(any.bounded());
  EXPECT_TRUE(any.contains(-1e300));
  EXPECT_FALSE(any.contains(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(any.contains(std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(closed.bounded());
}

TEST(ParameterRange, TextShowsTheEndsAsAFileWouldGiveThem) {
  EXPECT_EQ((Range{3, 15}).text(), "[3, 15]");
  EXPECT_EQ(Range::above(0, 100).text(), "(0, 100]");
  EXPECT_EQ(Range::below(0, 1).text(), "[0, 1)");
  EXPECT_EQ(Range::open(0.3, 20).text(), "(0.3, 20)");
  EXPECT_EQ((Range{-1e5, 1e5}).text(), "[-100000, 100000]");
  EXPECT_EQ(parameter_number_text(0.4), "0.4");
  EXPECT_EQ(parameter_number_text(-127.8), "-127.8");
  EXPECT_EQ(parameter_number_text(2.5e-5), "2.5e-05");
  EXPECT_EQ(parameter_number_text(1099511627776.0), "1099511627776");
  EXPECT_EQ(std::stod(parameter_number_text(0.1 * 3)), 0.1 * 3);  // reads back exactly
}

TEST(ParameterChoices, NameListAndParseAnEnum) {
  EXPECT_EQ(choice_name(Flavour::kBitter), "bitter");
  EXPECT_EQ(choice_list<Flavour>(), "sweet, sour or bitter");
  Flavour flavour = Flavour::kSweet;
  EXPECT_TRUE(parse_choice("bitter", flavour));
  EXPECT_EQ(flavour, Flavour::kBitter);
  EXPECT_FALSE(parse_choice("salty", flavour));
  EXPECT_EQ(flavour, Flavour::kBitter);
  EXPECT_TRUE(ChoiceParameter<Flavour>);
}

TEST(ParameterVisitor, ConceptsTellStructsWithAVisitFromOthers) {
  EXPECT_TRUE(VisitableParameters<Outer>);
  EXPECT_TRUE(VisitableParameters<CosmosParameters>);
  EXPECT_FALSE(VisitableParameters<NoVisit>);
  EXPECT_FALSE(VisitableParameters<int>);
}

TEST(ParameterVisitor, AVisitorSeesEveryDeclarationInOrder) {
  Recorder recorder;
  const Outer outer;  // a const struct is visited through the same visit()
  visit_parameters(recorder, outer);
  const std::vector<std::string> expected = {"length_mm|a length, mm|(0, 10]",
                                             "flavour|a flavour|",
                                             "retired size_mm -> length_mm",
                                             "inner|a nested map|",
                                             "count|how many|[1, 9]",
                                             "end inner",
                                             "fields",
                                             "count|how many|[1, 9]"};
  EXPECT_EQ(recorder.calls, expected);
}

// A visitor that writes: the struct's own fields change.
struct Doubler {
  template <class T>
  void operator()(const char*, T& field, const char*, const Range& = {}) {
    if constexpr (VisitableParameters<T>) {
      visit_parameters(*this, field);
    } else if constexpr (std::is_arithmetic_v<T>) {
      field = static_cast<T>(field * 2);
    }
  }
  template <class T>
  void fields(T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char*, const char*) {}
};

TEST(ParameterVisitor, AWritingVisitorReachesNestedAndInlinedFields) {
  Outer outer;
  Doubler doubler;
  visit_parameters(doubler, outer);
  EXPECT_EQ(outer.length_mm, 5.0);
  EXPECT_EQ(outer.inner.count, 6);
  EXPECT_EQ(outer.inlined.count, 6);
  EXPECT_EQ(outer.flavour, Flavour::kSour);
}

}  // namespace
}  // namespace cosmos
