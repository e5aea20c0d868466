#pragma once
// Interreflections in an empty rectangular room seen as three uniform surfaces: floor (the
// lower reference plane), walls and ceiling (the upper one), each of uniform exitance; the flux
// transfer model behind CIE 190's background luminance [CIE190] (its transfer factors F_T come
// from this model: tests/calc/ugr_table_test.cpp reproduces its printed values).
namespace luxgrid::calc::glare {

struct ThreeSurfaces {
  double floor = 0.0, walls = 0.0, ceiling = 0.0;
};

// Form factor between two directly opposed, equal, parallel a x b rectangles at distance c
// ([Howell] catalogue C-11); in (0, 1) for positive sizes.
double parallel_rectangles_form_factor(double a_m, double b_m, double c_m);

// The indirect flux arriving on each surface (lm) of an X x Y room of height H whose surfaces
// receive `direct_lm` directly from the luminaires and reflect diffusely with `reflectance`
// (each below 1): the exitances solve M_i = rho_i (D_i + sum_j M_j F_ji), and surface i then
// receives sum_j M_j F_ji.
ThreeSurfaces indirect_flux(double X_m, double Y_m, double H_m, const ThreeSurfaces& reflectance,
                            const ThreeSurfaces& direct_lm);

}  // namespace luxgrid::calc::glare
