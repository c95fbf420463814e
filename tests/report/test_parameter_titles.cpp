// Study plots title their axes with the parameter's name and unit in words
// (issue 24 item 5: "axis titles are raw key paths") and put a tick on every
// row and column of the study (the map's ticks 2e6, 4e6, ... did not mark its
// rows 2, 4.5, 7, 9.5, 12e6).
#include <gtest/gtest.h>

#include <railstab/report/parameter_titles.hpp>

#include <regex>
#include <string>

using namespace railstab;

TEST(ParameterAxisTitle, NameOwnerAndUnitInWords) {
  EXPECT_EQ(parameter_axis_title("elements.yaw_damper_front.damping_N_s_per_m"),
            "yaw damper front: damping [N s/m]");
  EXPECT_EQ(parameter_axis_title("bodies.carbody.mass_kg"), "carbody: mass [kg]");
  EXPECT_EQ(parameter_axis_title("elements.primary.stiffness_N_per_m[1]"),
            "primary: stiffness, y [N/m]");
  EXPECT_EQ(parameter_axis_title("contacts.textbook_linear.conicity"), "textbook linear: conicity");
  EXPECT_EQ(parameter_axis_title("speed_m_per_s"), "speed [m/s]");
  EXPECT_EQ(parameter_axis_title("bodies.carbody.inertia_kg_m2[2]"), "carbody: inertia, z [kg m^2]");
  // The first word is the quantity even when it is also a unit word.
  EXPECT_EQ(parameter_axis_title("contacts.c.m"), "c: m");
  EXPECT_EQ(parameter_axis_title("elements.primary.stiffness_N_per_m[0],elements.primary.stiffness_N_per_m[1]"),
            "primary: stiffness, x [N/m] = primary: stiffness, y [N/m]");  // linked keys
  // An index beyond a 3-vector is named by number.
  EXPECT_EQ(parameter_axis_title("elements.d.table_N[4]"), "d: table, component 4 [N]");
}

TEST(GnuplotValueTics, ATickOnEveryValueUpToTheLimit) {
  const std::string tics = gnuplot_value_tics({2e6, 4.5e6, 7e6, 9.5e6, 12e6});
  EXPECT_EQ(tics, "('2e6' 2000000, '4.5e6' 4500000, '7e6' 7000000, '9.5e6' 9500000, "
                  "'1.2e7' 12000000)");
  EXPECT_EQ(gnuplot_value_tics({1.5e-5, 250}), "('1.5e-5' 1.5e-05, '250' 250)");
  // 25 values, at most 12 ticks: every third, the last kept.
  std::vector<double> v;
  for (int k = 0; k < 25; ++k) v.push_back(k);
  const std::string many = gnuplot_value_tics(v, 12);
  const std::regex label("'[^']*'");
  const auto n = std::distance(std::sregex_iterator(many.begin(), many.end(), label),
                               std::sregex_iterator());
  EXPECT_LE(n, 12);
  EXPECT_GE(n, 8);
  EXPECT_NE(many.find("'0' 0"), std::string::npos);
  EXPECT_NE(many.find("'24' 24"), std::string::npos);
}
