// rt export-web's term switches, as rt view's panel zeroes them (render/prepare.h's
// switch_off_terms): before a pixel is traced, main calls rt_apply_terms, which zeroes the
// coefficients the page has switched off in every material, or makes the environment none.
// Bit i of rt_terms_off is kTermNames[i] (the kTerm* constants of the prelude). The page's
// shader declares materials and environment without `const` for it.
uniform int rt_terms_off;

void rt_apply_terms() {
    for (int i = 0; i < material_count; ++i) {
        if ((rt_terms_off & kTermAmbient) != 0) materials[i].ambient.rgb = vec3(0.0);
        if ((rt_terms_off & kTermDiffuse) != 0) materials[i].diffuse.rgb = vec3(0.0);
        if ((rt_terms_off & kTermSpecular) != 0) materials[i].specular_shininess.rgb = vec3(0.0);
        if ((rt_terms_off & kTermEmissive) != 0) materials[i].emissive.rgb = vec3(0.0);
        if ((rt_terms_off & kTermReflection) != 0) materials[i].reflective.rgb = vec3(0.0);
        if ((rt_terms_off & kTermRefraction) != 0) materials[i].transmissive_ior.rgb = vec3(0.0);
    }
    if ((rt_terms_off & kTermEnvironment) != 0) environment[0].kind_image.x = kEnvironmentNone;
}
