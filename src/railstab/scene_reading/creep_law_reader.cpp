#include <railstab/scene_reading/creep_law_reader.hpp>

#include <array>
#include <stdexcept>
#include <variant>

namespace railstab::scene_reading {

namespace {
// The creep_law names are the laws' own (kName).
enum class CreepLawChoice { linear_kalker, shen_hedrick_elkins, polach };
const Choices<CreepLawChoice> kCreepLaws = {
    {LinearKalkerCreep<double>::kName, CreepLawChoice::linear_kalker},
    {ShenHedrickElkinsCreep<double>::kName, CreepLawChoice::shen_hedrick_elkins},
    {PolachCreep<double>::kName, CreepLawChoice::polach}};
const std::array<std::string_view, 5> kPolachKeys = {
    "polach_limit_friction_ratio", "polach_friction_decrease_s_per_m",
    "polach_adhesion_reduction_factor", "polach_slip_reduction_factor", ""};
}  // namespace

const std::vector<std::string_view>& creep_law_keys() {
  static const std::vector<std::string_view> keys = {
      "creep_law", "friction_coefficient", "kalker_reduction_factor",
      "polach_limit_friction_ratio", "polach_friction_decrease_s_per_m",
      "polach_adhesion_reduction_factor", "polach_slip_reduction_factor"};
  return keys;
}

CreepLawSpec read_creep_law(const TableReader& contact, const ContactSpec& spec) {
  const CreepLawChoice choice =
      contact.choice_or("creep_law", kCreepLaws, CreepLawChoice::linear_kalker);
  const double reduction = contact.number_or("kalker_reduction_factor", "", 1.0);
  if (!(reduction > 0.0 && reduction <= 1.0))
    contact.fail("kalker_reduction_factor", "a number in (0, 1]", format_number(reduction));
  if (choice != CreepLawChoice::polach)
    for (std::string_view key : kPolachKeys)
      if (!key.empty())
        contact.reject_if_present(key, "no " + std::string(key) +
                                           " unless creep_law = \"polach\"");
  auto friction = [&](double fallback) {
    const double mu = contact.number_or("friction_coefficient", "", fallback);
    if (!(mu > 0.0 && mu <= 2.0))
      contact.fail("friction_coefficient", "a number in (0, 2]", format_number(mu));
    return mu;
  };
  CreepLawSpec law;
  switch (choice) {
    case CreepLawChoice::linear_kalker: {
      contact.reject_if_present("friction_coefficient",
                                "no friction_coefficient with creep_law = \"linear_kalker\" (linear "
                                "creep never saturates; choose shen_hedrick_elkins or polach)");
      law = LinearKalkerCreep<double>{reduction};
      break;
    }
    case CreepLawChoice::shen_hedrick_elkins: {
      ShenHedrickElkinsCreep<double> she;
      she.friction_coefficient = friction(she.friction_coefficient);
      she.kalker_reduction_factor = reduction;
      law = she;
      break;
    }
    case CreepLawChoice::polach: {
      if (spec.tangential != TangentialForceKind::kalker_hertz)
        contact.fail("creep_law", "tangential = \"kalker_hertz\" for Polach's method (it needs the "
                                  "contact ellipse)",
                     "'polach' with another tangential model");
      PolachCreep<double> p;
      p.friction_coefficient = friction(p.friction_coefficient);
      p.kalker_reduction_factor = reduction;
      p.limit_friction_ratio = contact.number_or("polach_limit_friction_ratio", "", p.limit_friction_ratio);
      p.friction_decrease_rate_s_per_m =
          contact.number_or("polach_friction_decrease_s_per_m", "s/m", p.friction_decrease_rate_s_per_m);
      p.adhesion_reduction_factor =
          contact.number_or("polach_adhesion_reduction_factor", "", p.adhesion_reduction_factor);
      p.slip_reduction_factor =
          contact.number_or("polach_slip_reduction_factor", "", p.slip_reduction_factor);
      law = p;
      break;
    }
  }
  try {
    std::visit([](const auto& l) { l.validate(); }, law);
  } catch (const std::invalid_argument& e) {
    contact.fail("creep_law", "parameters a creep law accepts", e.what());
  }
  return law;
}

}  // namespace railstab::scene_reading
