#pragma once
// A wheel-rail contact model as the model holds it: the scene's description
// and what is derived from it once (combined elastic constants, rail
// curvature).
//
// S is the scalar of the parameters (model/model.hpp): the contact parameters
// an engineer may want sensitivities for (cone angle, conicity and the creep
// law's friction coefficient and reduction factors) are held as S, so the
// exact derivative of the state matrix with respect to them is available
// (sensitivity/parameter_derivative.hpp); the evaluation reads them from
// here, never from `spec`, whose copies of them are the scene's values.
#include <railstab/contact/hertz.hpp>
#include <railstab/contact/contact_spec.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>

#include <variant>

namespace railstab {

// f(key, -1, value&) for the parameters that a contact described by `spec`
// uses: the scene's (ContactSpec) and the model's (ModelContactTpl) alike.
template <class S, class F>
void visit_contact_parameters(const ContactSpec& spec, S& cone_angle_rad, S& conicity,
                              CreepLawTpl<S>& creep_law, F&& f) {
  if (spec.geometry == ContactGeometryKind::knife_edge_cone) f("cone_angle_rad", -1, cone_angle_rad);
  if (spec.geometry == ContactGeometryKind::linear_conicity) f("conicity", -1, conicity);
  if (spec.tangential != TangentialForceKind::none)
    std::visit([&](auto& law) { law.for_each_parameter(f); }, creep_law);
}

template <class S> struct ModelContactTpl {
  ContactSpec spec;
  ElasticPair materials{};
  double rail_curvature_B_per_m = 0.0;  // B = 1 / (2 R_rail), transverse
  S cone_angle_rad{0.0};                // knife_edge_cone: gamma
  S conicity{0.0};                      // linear_conicity: lambda
  CreepLawTpl<S> creep_law;

  // f(scene key, -1, value&) for each parameter this contact uses (its
  // geometry's and its creep law's): sensitivity keys contacts.<name>.<key>.
  template <class F> void for_each_parameter(F&& f) {
    visit_contact_parameters(spec, cone_angle_rad, conicity, creep_law, f);
  }

  template <class S2> ModelContactTpl<S2> cast() const {
    ModelContactTpl<S2> c;
    c.spec = spec;
    c.materials = materials;
    c.rail_curvature_B_per_m = rail_curvature_B_per_m;
    c.cone_angle_rad = cast_parameter<S2>(cone_angle_rad);
    c.conicity = cast_parameter<S2>(conicity);
    c.creep_law = std::visit(
        [](const auto& law) -> CreepLawTpl<S2> { return law.template cast<S2>(); }, creep_law);
    return c;
  }
};

using ModelContact = ModelContactTpl<double>;

// The lateral shift of a wheelset beyond which the contact model no longer
// holds: the flange clearance of the flangeless geometries (flange contact
// is not modelled), the contact table's lateral half range for profiles
// (beyond it the wheel has climbed off its rail).
inline double lateral_validity_limit_m(const ContactSpec& spec) {
  if (spec.geometry == ContactGeometryKind::table && spec.profile_geometry)
    return spec.profile_geometry->table.options().lateral_half_range_m;  // the file's grid
  return uses_contact_table(spec.geometry) ? spec.profile_source.table.lateral_half_range_m
                                           : spec.flange_clearance_m;
}

// The model's contact from the scene's description.
inline ModelContact make_model_contact(const ContactSpec& spec) {
  ModelContact c;
  c.spec = spec;
  c.materials = combine_materials(spec.wheel_young_modulus_Pa, spec.wheel_poisson_ratio,
                                  spec.rail_young_modulus_Pa, spec.rail_poisson_ratio);
  c.rail_curvature_B_per_m = 0.5 / spec.rail_head_transverse_radius_m;
  c.cone_angle_rad = spec.cone_angle_rad;
  c.conicity = spec.conicity;
  c.creep_law = spec.creep_law;
  return c;
}

}  // namespace railstab
