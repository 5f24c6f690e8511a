#define WP_NO_BFLOAT16

#define WP_TILE_BLOCK_DIM 1
#define WP_NO_CRT
#include "builtin.h"
#include "deterministic.h"

#define builtin_tid1d() wp::linear_tid<wp_linear_tid>(task_index, dim)
#define builtin_tid2d(x, y) wp::tid(x, y, task_index, dim)
#define builtin_tid3d(x, y, z) wp::tid(x, y, z, task_index, dim)
#define builtin_tid4d(x, y, z, w) wp::tid(x, y, z, w, task_index, dim)

#define builtin_block_dim() wp::block_dim()


// avoid namespacing of float type for casting to float type, this is to avoid wp::float(x), which is not valid in C++
#define float(x) cast_float(x)
#define adj_float(x, adj_x, adj_ret) adj_cast_float(x, adj_x, adj_ret)

#define int(x) cast_int(x)
#define adj_int(x, adj_x, adj_ret) adj_cast_int(x, adj_x, adj_ret)


struct Bsdf_4cf4d8bd
{
    wp::float32 diffuse;
    wp::float32 f0;
    wp::float32 f90;
    wp::float32 alpha;
    wp::float32 coat;
    wp::float32 coat_alpha;


    Bsdf_4cf4d8bd() = default;
    CUDA_CALLABLE Bsdf_4cf4d8bd(wp::float32 const& diffuse,
    wp::float32 const& f0 = {},
    wp::float32 const& f90 = {},
    wp::float32 const& alpha = {},
    wp::float32 const& coat = {},
    wp::float32 const& coat_alpha = {})
        : diffuse{diffuse}
        , f0{f0}
        , f90{f90}
        , alpha{alpha}
        , coat{coat}
        , coat_alpha{coat_alpha}

    {
    }

    CUDA_CALLABLE Bsdf_4cf4d8bd& operator += (const Bsdf_4cf4d8bd& rhs)
    {    diffuse += rhs.diffuse;
    f0 += rhs.f0;
    f90 += rhs.f90;
    alpha += rhs.alpha;
    coat += rhs.coat;
    coat_alpha += rhs.coat_alpha;

        return *this;}

};

static CUDA_CALLABLE void adj_Bsdf_4cf4d8bd(wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 & adj_diffuse,
    wp::float32 & adj_f0,
    wp::float32 & adj_f90,
    wp::float32 & adj_alpha,
    wp::float32 & adj_coat,
    wp::float32 & adj_coat_alpha,
    Bsdf_4cf4d8bd & adj_ret)
{
    adj_diffuse += adj_ret.diffuse;
    adj_f0 += adj_ret.f0;
    adj_f90 += adj_ret.f90;
    adj_alpha += adj_ret.alpha;
    adj_coat += adj_ret.coat;
    adj_coat_alpha += adj_ret.coat_alpha;
}

// Required when compiling adjoints.
CUDA_CALLABLE Bsdf_4cf4d8bd add(const Bsdf_4cf4d8bd& a, const Bsdf_4cf4d8bd& b)
{
    return Bsdf_4cf4d8bd();
}

CUDA_CALLABLE void adj_atomic_add(Bsdf_4cf4d8bd* p, Bsdf_4cf4d8bd t)
{
    wp::adj_atomic_add(&p->diffuse, t.diffuse);
    wp::adj_atomic_add(&p->f0, t.f0);
    wp::adj_atomic_add(&p->f90, t.f90);
    wp::adj_atomic_add(&p->alpha, t.alpha);
    wp::adj_atomic_add(&p->coat, t.coat);
    wp::adj_atomic_add(&p->coat_alpha, t.coat_alpha);
}




// /work/main/simulator/kernels/bsdf.py:63
static Bsdf_4cf4d8bd preview_bsdf_0(
    wp::float32 var_rho,
    wp::float32 var_roughness,
    wp::float32 var_metallic,
    wp::float32 var_ior,
    wp::float32 var_specular,
    wp::int32 var_workflow,
    wp::float32 var_coat,
    wp::float32 var_coat_roughness)
{
    //---------
    // primal vars
    Bsdf_4cf4d8bd var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    const wp::float32 var_3 = 1.0;
    const wp::float32 var_4 = 1.0;
    wp::float32 var_5;
    const wp::float32 var_6 = 1.0;
    wp::float32 var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = 1.0;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    const wp::float32 var_15 = 1.0;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::float32 var_18;
    const wp::float32 var_19 = 1.0;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    //---------
    // forward
    // def preview_bsdf(rho: float, roughness: float, metallic: float, ior: float, specular: float, workflow: int,       <L 64>
    // b = Bsdf()                                                                             <L 68>
    var_0 = Bsdf_4cf4d8bd();
    // if workflow != 0:                                                                      <L 69>
    var_2 = (var_workflow != var_1);
    if (var_2) {
        // b.f0 = specular                                                                    <L 70>
        var_0.f0 = var_specular;
        // b.f90 = 1.0                                                                        <L 71>
        var_0.f90 = var_3;
        // b.diffuse = rho                                                                    <L 72>
        var_0.diffuse = var_rho;
    }
    if (!var_2) {
        // r = (1.0 - ior) / (1.0 + ior)                                                      <L 74>
        var_5 = wp::sub(var_4, var_ior);
        var_7 = wp::add(var_6, var_ior);
        var_8 = wp::div(var_5, var_7);
        // b.f0 = (1.0 - metallic) * r * r + metallic * rho                                   <L 75>
        var_10 = wp::sub(var_9, var_metallic);
        var_11 = wp::mul(var_10, var_8);
        var_12 = wp::mul(var_11, var_8);
        var_13 = wp::mul(var_metallic, var_rho);
        var_14 = wp::add(var_12, var_13);
        var_0.f0 = var_14;
        // b.f90 = (1.0 - metallic) + metallic * rho                                          <L 76>
        var_16 = wp::sub(var_15, var_metallic);
        var_17 = wp::mul(var_metallic, var_rho);
        var_18 = wp::add(var_16, var_17);
        var_0.f90 = var_18;
        // b.diffuse = (1.0 - metallic) * rho                                                 <L 77>
        var_20 = wp::sub(var_19, var_metallic);
        var_21 = wp::mul(var_20, var_rho);
        var_0.diffuse = var_21;
    }
    // b.alpha = roughness * roughness                                                        <L 78>
    var_22 = wp::mul(var_roughness, var_roughness);
    var_0.alpha = var_22;
    // b.coat = coat                                                                          <L 79>
    var_0.coat = var_coat;
    // b.coat_alpha = coat_roughness * coat_roughness                                         <L 80>
    var_23 = wp::mul(var_coat_roughness, var_coat_roughness);
    var_0.coat_alpha = var_23;
    // return b                                                                               <L 81>
    return var_0;
}


// /work/main/tests/test_bsdf.py:33
static Bsdf_4cf4d8bd _lobes_0(
    wp::vec_t<4, wp::float32> var_p,
    wp::vec_t<4, wp::float32> var_q)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::int32 var_1;
    const wp::int32 var_2 = 0;
    wp::float32 var_3;
    const wp::float32 var_4 = 0.0;
    bool var_5;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    const wp::int32 var_8 = 0;
    wp::float32 var_9;
    const wp::int32 var_10 = 1;
    wp::float32 var_11;
    const wp::int32 var_12 = 2;
    wp::float32 var_13;
    const wp::int32 var_14 = 3;
    wp::float32 var_15;
    const wp::int32 var_16 = 0;
    wp::float32 var_17;
    const wp::int32 var_18 = 1;
    wp::float32 var_19;
    const wp::int32 var_20 = 2;
    wp::float32 var_21;
    Bsdf_4cf4d8bd var_22;
    //---------
    // forward
    // def _lobes(p: wp.vec4, q: wp.vec4) -> Bsdf:                                            <L 34>
    // wf = int(0)                                                                            <L 36>
    var_1 = wp::int(var_0);
    // if q[0] >= 0.0:                                                                        <L 37>
    var_3 = wp::extract(var_q, var_2);
    var_5 = (var_3 >= var_4);
    if (var_5) {
        // wf = 1                                                                             <L 38>
    }
    var_7 = wp::where(var_5, var_6, var_1);
    // return preview_bsdf(p[0], p[1], p[2], p[3], q[0], wf, q[1], q[2])                      <L 39>
    var_9 = wp::extract(var_p, var_8);
    var_11 = wp::extract(var_p, var_10);
    var_13 = wp::extract(var_p, var_12);
    var_15 = wp::extract(var_p, var_14);
    var_17 = wp::extract(var_q, var_16);
    var_19 = wp::extract(var_q, var_18);
    var_21 = wp::extract(var_q, var_20);
    var_22 = preview_bsdf_0(var_9, var_11, var_13, var_15, var_17, var_7, var_19, var_21);
    return var_22;
}


// /work/main/simulator/kernels/bsdf.py:84
static wp::float32 schlick_0(
    wp::float32 var_f0,
    wp::float32 var_f90,
    wp::float32 var_c)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 1.0;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    const wp::float32 var_3 = 1.0;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    //---------
    // forward
    // def schlick(f0: float, f90: float, c: float) -> float:                                 <L 85>
    // m = wp.clamp(1.0 - c, 0.0, 1.0)                                                        <L 87>
    var_1 = wp::sub(var_0, var_c);
    var_4 = wp::clamp(var_1, var_2, var_3);
    // m2 = m * m                                                                             <L 88>
    var_5 = wp::mul(var_4, var_4);
    // return f0 + (f90 - f0) * m2 * m2 * m                                                   <L 89>
    var_6 = wp::sub(var_f90, var_f0);
    var_7 = wp::mul(var_6, var_5);
    var_8 = wp::mul(var_7, var_5);
    var_9 = wp::mul(var_8, var_4);
    var_10 = wp::add(var_f0, var_9);
    return var_10;
}


// /work/main/simulator/kernels/bsdf.py:170
static wp::float32 diffuse_f_0(
    Bsdf_4cf4d8bd var_b,
    wp::float32 var_ci,
    wp::float32 var_co)
{
    //---------
    // primal vars
    wp::float32* var_0;
    const wp::float32 var_1 = 0.318309886183791;
    wp::float32 var_2;
    wp::float32 var_3;
    const wp::float32 var_4 = 1.0;
    wp::float32* var_5;
    wp::float32* var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    const wp::float32 var_12 = 1.0;
    wp::float32* var_13;
    wp::float32* var_14;
    wp::float32 var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    //---------
    // forward
    // def diffuse_f(b: Bsdf, ci: float, co: float) -> float:                                 <L 171>
    // return b.diffuse * INV_PI_B * (1.0 - schlick(b.f0, b.f90, ci)) * (1.0 - schlick(b.f0, b.f90, co))       <L 173>
    var_0 = &((var_b).diffuse);
    var_3 = wp::load(var_0);
    var_2 = wp::mul(var_3, var_1);
    var_5 = &((var_b).f0);
    var_6 = &((var_b).f90);
    var_8 = wp::load(var_5);
    var_9 = wp::load(var_6);
    var_7 = schlick_0(var_8, var_9, var_ci);
    var_10 = wp::sub(var_4, var_7);
    var_11 = wp::mul(var_2, var_10);
    var_13 = &((var_b).f0);
    var_14 = &((var_b).f90);
    var_16 = wp::load(var_13);
    var_17 = wp::load(var_14);
    var_15 = schlick_0(var_16, var_17, var_co);
    var_18 = wp::sub(var_12, var_15);
    var_19 = wp::mul(var_11, var_18);
    return var_19;
}


// /work/main/simulator/kernels/bsdf.py:146
static bool is_delta_specular_0(
    Bsdf_4cf4d8bd var_b)
{
    //---------
    // primal vars
    wp::float32* var_0;
    const wp::float32 var_1 = 0.01;
    wp::float32 var_2;
    bool var_3;
    wp::float32 var_4;
    //---------
    // forward
    // def is_delta_specular(b: Bsdf) -> bool:                                                <L 147>
    // return b.alpha <= DELTA_ROUGHNESS * DELTA_ROUGHNESS                                    <L 149>
    var_0 = &((var_b).alpha);
    var_2 = wp::mul(var_1, var_1);
    var_4 = wp::load(var_0);
    var_3 = (var_4 <= var_2);
    return var_3;
}


// /work/main/simulator/kernels/bsdf.py:92
static wp::float32 ggx_d_0(
    wp::float32 var_cos_h,
    wp::float32 var_alpha)
{
    //---------
    // primal vars
    wp::float32 var_0;
    wp::float32 var_1;
    const wp::float32 var_2 = 1.0;
    wp::float32 var_3;
    wp::float32 var_4;
    const wp::float32 var_5 = 1.0;
    wp::float32 var_6;
    const wp::float32 var_7 = 0.318309886183791;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    //---------
    // forward
    // def ggx_d(cos_h: float, alpha: float) -> float:                                        <L 93>
    // a2 = alpha * alpha                                                                     <L 95>
    var_0 = wp::mul(var_alpha, var_alpha);
    // t = cos_h * cos_h * (a2 - 1.0) + 1.0                                                   <L 96>
    var_1 = wp::mul(var_cos_h, var_cos_h);
    var_3 = wp::sub(var_0, var_2);
    var_4 = wp::mul(var_1, var_3);
    var_6 = wp::add(var_4, var_5);
    // return a2 * INV_PI_B / (t * t)                                                         <L 97>
    var_8 = wp::mul(var_0, var_7);
    var_9 = wp::mul(var_6, var_6);
    var_10 = wp::div(var_8, var_9);
    return var_10;
}


// /work/main/simulator/kernels/bsdf.py:100
static wp::float32 ggx_lambda_0(
    wp::float32 var_c,
    wp::float32 var_alpha)
{
    //---------
    // primal vars
    wp::float32 var_0;
    const wp::float32 var_1 = 0.0;
    const wp::float32 var_2 = 1.0;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    const wp::float32 var_6 = 0.5;
    const wp::float32 var_7 = 1.0;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    const wp::float32 var_12 = 1.0;
    wp::float32 var_13;
    wp::float32 var_14;
    //---------
    // forward
    // def ggx_lambda(c: float, alpha: float) -> float:                                       <L 101>
    // c2 = c * c                                                                             <L 103>
    var_0 = wp::mul(var_c, var_c);
    // tan2 = wp.max(0.0, 1.0 - c2) / c2                                                      <L 104>
    var_3 = wp::sub(var_2, var_0);
    var_4 = wp::max(var_1, var_3);
    var_5 = wp::div(var_4, var_0);
    // return 0.5 * (wp.sqrt(1.0 + alpha * alpha * tan2) - 1.0)                               <L 105>
    var_8 = wp::mul(var_alpha, var_alpha);
    var_9 = wp::mul(var_8, var_5);
    var_10 = wp::add(var_7, var_9);
    var_11 = wp::sqrt(var_10);
    var_13 = wp::sub(var_11, var_12);
    var_14 = wp::mul(var_6, var_13);
    return var_14;
}


// /work/main/simulator/kernels/bsdf.py:108
static wp::float32 ggx_g2_0(
    wp::float32 var_ci,
    wp::float32 var_co,
    wp::float32 var_alpha)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 1.0;
    const wp::float32 var_1 = 1.0;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    //---------
    // forward
    // def ggx_g2(ci: float, co: float, alpha: float) -> float:                               <L 109>
    // return 1.0 / (1.0 + ggx_lambda(ci, alpha) + ggx_lambda(co, alpha))                     <L 111>
    var_2 = ggx_lambda_0(var_ci, var_alpha);
    var_3 = wp::add(var_1, var_2);
    var_4 = ggx_lambda_0(var_co, var_alpha);
    var_5 = wp::add(var_3, var_4);
    var_6 = wp::div(var_0, var_5);
    return var_6;
}


// /work/main/simulator/kernels/bsdf.py:114
static wp::float32 microfacet_f_0(
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo,
    wp::float32 var_alpha,
    wp::float32 var_f0,
    wp::float32 var_f90)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::int32 var_2 = 2;
    wp::float32 var_3;
    bool var_4;
    const wp::float32 var_5 = 0.0;
    bool var_6;
    const wp::float32 var_7 = 0.0;
    bool var_8;
    const wp::float32 var_9 = 0.0;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<3, wp::float32> var_11;
    const wp::int32 var_12 = 2;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    const wp::float32 var_20 = 4.0;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    //---------
    // forward
    // def microfacet_f(wi: wp.vec3, wo: wp.vec3, alpha: float, f0: float, f90: float) -> float:       <L 115>
    // ci = wi[2]                                                                             <L 117>
    var_1 = wp::extract(var_wi, var_0);
    // co = wo[2]                                                                             <L 118>
    var_3 = wp::extract(var_wo, var_2);
    // if ci <= 0.0 or co <= 0.0:                                                             <L 119>
    var_6 = (var_1 <= var_5);
    var_4 = var_6;
    if (!var_4) {
        var_8 = (var_3 <= var_7);
        var_4 = var_4 || var_8;
    }
    if (var_4) {
        // return 0.0                                                                         <L 120>
        return var_9;
    }
    // h = wp.normalize(wi + wo)                                                              <L 121>
    var_10 = wp::add(var_wi, var_wo);
    var_11 = wp::normalize(var_10);
    // return ggx_d(h[2], alpha) * ggx_g2(ci, co, alpha) * schlick(f0, f90, wp.dot(wi, h)) / (4.0 * ci * co)       <L 122>
    var_13 = wp::extract(var_11, var_12);
    var_14 = ggx_d_0(var_13, var_alpha);
    var_15 = ggx_g2_0(var_1, var_3, var_alpha);
    var_16 = wp::mul(var_14, var_15);
    var_17 = wp::dot(var_wi, var_11);
    var_18 = schlick_0(var_f0, var_f90, var_17);
    var_19 = wp::mul(var_16, var_18);
    var_21 = wp::mul(var_20, var_1);
    var_22 = wp::mul(var_21, var_3);
    var_23 = wp::div(var_19, var_22);
    return var_23;
}


// /work/main/simulator/kernels/bsdf.py:164
static wp::float32 coat_factor_0(
    Bsdf_4cf4d8bd var_b,
    wp::float32 var_c)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 1.0;
    wp::float32* var_1;
    const wp::float32 var_2 = 0.04;
    const wp::float32 var_3 = 1.0;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    //---------
    // forward
    // def coat_factor(b: Bsdf, c: float) -> float:                                           <L 165>
    // return 1.0 - b.coat * schlick(COAT_F0, 1.0, c)                                         <L 167>
    var_1 = &((var_b).coat);
    var_4 = schlick_0(var_2, var_3, var_c);
    var_6 = wp::load(var_1);
    var_5 = wp::mul(var_6, var_4);
    var_7 = wp::sub(var_0, var_5);
    return var_7;
}


// /work/main/simulator/kernels/bsdf.py:152
static bool is_delta_coat_0(
    Bsdf_4cf4d8bd var_b)
{
    //---------
    // primal vars
    bool var_0;
    wp::float32* var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    wp::float32 var_4;
    wp::float32* var_5;
    const wp::float32 var_6 = 0.01;
    wp::float32 var_7;
    bool var_8;
    wp::float32 var_9;
    //---------
    // forward
    // def is_delta_coat(b: Bsdf) -> bool:                                                    <L 153>
    // return b.coat > 0.0 and b.coat_alpha <= DELTA_ROUGHNESS * DELTA_ROUGHNESS              <L 155>
    var_1 = &((var_b).coat);
    var_4 = wp::load(var_1);
    var_3 = (var_4 > var_2);
    var_0 = var_3;
    if (var_0) {
        var_5 = &((var_b).coat_alpha);
        var_7 = wp::mul(var_6, var_6);
        var_9 = wp::load(var_5);
        var_8 = (var_9 <= var_7);
        var_0 = var_0 && var_8;
    }
    return var_0;
}


// /work/main/simulator/kernels/bsdf.py:176
static wp::float32 bsdf_f_0(
    Bsdf_4cf4d8bd var_b,
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::int32 var_2 = 2;
    wp::float32 var_3;
    bool var_4;
    const wp::float32 var_5 = 0.0;
    bool var_6;
    const wp::float32 var_7 = 0.0;
    bool var_8;
    const wp::float32 var_9 = 0.0;
    wp::float32 var_10;
    bool var_11;
    bool var_12;
    wp::float32* var_13;
    wp::float32* var_14;
    wp::float32* var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32* var_23;
    const wp::float32 var_24 = 0.0;
    bool var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    bool var_31;
    bool var_32;
    wp::float32* var_33;
    wp::float32* var_34;
    const wp::float32 var_35 = 0.04;
    const wp::float32 var_36 = 1.0;
    wp::float32 var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    //---------
    // forward
    // def bsdf_f(b: Bsdf, wi: wp.vec3, wo: wp.vec3) -> float:                                <L 177>
    // ci = wi[2]                                                                             <L 180>
    var_1 = wp::extract(var_wi, var_0);
    // co = wo[2]                                                                             <L 181>
    var_3 = wp::extract(var_wo, var_2);
    // if ci <= 0.0 or co <= 0.0:                                                             <L 182>
    var_6 = (var_1 <= var_5);
    var_4 = var_6;
    if (!var_4) {
        var_8 = (var_3 <= var_7);
        var_4 = var_4 || var_8;
    }
    if (var_4) {
        // return 0.0                                                                         <L 183>
        return var_9;
    }
    // base = diffuse_f(b, ci, co)                                                            <L 184>
    var_10 = diffuse_f_0(var_b, var_1, var_3);
    // if not is_delta_specular(b):                                                           <L 185>
    var_11 = is_delta_specular_0(var_b);
    var_12 = wp::unot(var_11);
    if (var_12) {
        // base += microfacet_f(wi, wo, b.alpha, b.f0, b.f90)                                 <L 186>
        var_13 = &((var_b).alpha);
        var_14 = &((var_b).f0);
        var_15 = &((var_b).f90);
        var_17 = wp::load(var_13);
        var_18 = wp::load(var_14);
        var_19 = wp::load(var_15);
        var_16 = microfacet_f_0(var_wi, var_wo, var_17, var_18, var_19);
        var_20 = wp::add(var_10, var_16);
    }
    var_21 = wp::where(var_12, var_20, var_10);
    // f = base                                                                               <L 187>
    var_22 = wp::copy(var_21);
    // if b.coat > 0.0:                                                                       <L 188>
    var_23 = &((var_b).coat);
    var_26 = wp::load(var_23);
    var_25 = (var_26 > var_24);
    if (var_25) {
        // f = coat_factor(b, ci) * coat_factor(b, co) * base                                 <L 189>
        var_27 = coat_factor_0(var_b, var_1);
        var_28 = coat_factor_0(var_b, var_3);
        var_29 = wp::mul(var_27, var_28);
        var_30 = wp::mul(var_29, var_21);
        // if not is_delta_coat(b):                                                           <L 190>
        var_31 = is_delta_coat_0(var_b);
        var_32 = wp::unot(var_31);
        if (var_32) {
            // f += b.coat * microfacet_f(wi, wo, b.coat_alpha, COAT_F0, 1.0)                 <L 191>
            var_33 = &((var_b).coat);
            var_34 = &((var_b).coat_alpha);
            var_38 = wp::load(var_34);
            var_37 = microfacet_f_0(var_wi, var_wo, var_38, var_35, var_36);
            var_40 = wp::load(var_33);
            var_39 = wp::mul(var_40, var_37);
            var_41 = wp::add(var_30, var_39);
        }
        var_42 = wp::where(var_32, var_41, var_30);
    }
    var_43 = wp::where(var_25, var_42, var_22);
    // return f                                                                               <L 192>
    return var_43;
}


// /work/main/simulator/kernels/bsdf.py:195
static wp::vec_t<3, wp::float32> lobe_weights_0(
    Bsdf_4cf4d8bd var_b,
    wp::float32 var_co)
{
    //---------
    // primal vars
    wp::float32* var_0;
    const wp::float32 var_1 = 0.04;
    const wp::float32 var_2 = 1.0;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32* var_6;
    wp::float32* var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 1.0;
    wp::float32 var_12;
    wp::float32 var_13;
    bool var_14;
    const wp::float32 var_15 = 0.0;
    wp::float32 var_16;
    const wp::float32 var_17 = 1.0;
    wp::float32 var_18;
    const wp::float32 var_19 = 1.0;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32* var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    bool var_25;
    const wp::float32 var_26 = 0.0;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    const wp::float32 var_30 = 0.0;
    bool var_31;
    const wp::float32 var_32 = 0.0;
    const wp::float32 var_33 = 0.0;
    const wp::float32 var_34 = 1.0;
    wp::vec_t<3, wp::float32> var_35;
    wp::float32 var_36;
    wp::float32 var_37;
    wp::float32 var_38;
    wp::vec_t<3, wp::float32> var_39;
    //---------
    // forward
    // def lobe_weights(b: Bsdf, co: float) -> wp.vec3:                                       <L 196>
    // wc = b.coat * schlick(COAT_F0, 1.0, co)                                                <L 199>
    var_0 = &((var_b).coat);
    var_3 = schlick_0(var_1, var_2, var_co);
    var_5 = wp::load(var_0);
    var_4 = wp::mul(var_5, var_3);
    // fs = schlick(b.f0, b.f90, co)                                                          <L 200>
    var_6 = &((var_b).f0);
    var_7 = &((var_b).f90);
    var_9 = wp::load(var_6);
    var_10 = wp::load(var_7);
    var_8 = schlick_0(var_9, var_10, var_co);
    // ws = (1.0 - wc) * fs                                                                   <L 201>
    var_12 = wp::sub(var_11, var_4);
    var_13 = wp::mul(var_12, var_8);
    // if is_delta_specular(b):                                                               <L 202>
    var_14 = is_delta_specular_0(var_b);
    if (var_14) {
        // ws = 0.0                                                                           <L 203>
    }
    var_16 = wp::where(var_14, var_15, var_13);
    // wd = (1.0 - wc) * (1.0 - fs) * b.diffuse                                               <L 204>
    var_18 = wp::sub(var_17, var_4);
    var_20 = wp::sub(var_19, var_8);
    var_21 = wp::mul(var_18, var_20);
    var_22 = &((var_b).diffuse);
    var_24 = wp::load(var_22);
    var_23 = wp::mul(var_21, var_24);
    // if is_delta_coat(b):                                                                   <L 205>
    var_25 = is_delta_coat_0(var_b);
    if (var_25) {
        // wc = 0.0                                                                           <L 206>
    }
    var_27 = wp::where(var_25, var_26, var_4);
    // tot = wc + ws + wd                                                                     <L 207>
    var_28 = wp::add(var_27, var_16);
    var_29 = wp::add(var_28, var_23);
    // if tot <= 0.0:                                                                         <L 208>
    var_31 = (var_29 <= var_30);
    if (var_31) {
        // return wp.vec3(0.0, 0.0, 1.0)                                                      <L 209>
        var_35 = wp::vec_t<3, wp::float32>(var_32, var_33, var_34);
        return var_35;
    }
    // return wp.vec3(wc / tot, ws / tot, wd / tot)                                           <L 210>
    var_36 = wp::div(var_27, var_29);
    var_37 = wp::div(var_16, var_29);
    var_38 = wp::div(var_23, var_29);
    var_39 = wp::vec_t<3, wp::float32>(var_36, var_37, var_38);
    return var_39;
}


// /work/main/simulator/kernels/bsdf.py:125
static wp::float32 microfacet_pdf_0(
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo,
    wp::float32 var_alpha)
{
    //---------
    // primal vars
    bool var_0;
    const wp::int32 var_1 = 2;
    wp::float32 var_2;
    const wp::float32 var_3 = 0.0;
    bool var_4;
    const wp::int32 var_5 = 2;
    wp::float32 var_6;
    const wp::float32 var_7 = 0.0;
    bool var_8;
    const wp::float32 var_9 = 0.0;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<3, wp::float32> var_11;
    const wp::int32 var_12 = 2;
    wp::float32 var_13;
    wp::float32 var_14;
    const wp::int32 var_15 = 2;
    wp::float32 var_16;
    wp::float32 var_17;
    const wp::float32 var_18 = 4.0;
    wp::float32 var_19;
    const wp::float32 var_20 = 1e-12;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    //---------
    // forward
    // def microfacet_pdf(wi: wp.vec3, wo: wp.vec3, alpha: float) -> float:                   <L 126>
    // if wi[2] <= 0.0 or wo[2] <= 0.0:                                                       <L 128>
    var_2 = wp::extract(var_wi, var_1);
    var_4 = (var_2 <= var_3);
    var_0 = var_4;
    if (!var_0) {
        var_6 = wp::extract(var_wo, var_5);
        var_8 = (var_6 <= var_7);
        var_0 = var_0 || var_8;
    }
    if (var_0) {
        // return 0.0                                                                         <L 129>
        return var_9;
    }
    // h = wp.normalize(wi + wo)                                                              <L 130>
    var_10 = wp::add(var_wi, var_wo);
    var_11 = wp::normalize(var_10);
    // return ggx_d(h[2], alpha) * h[2] / (4.0 * wp.max(wp.dot(wo, h), 1.0e-12))              <L 131>
    var_13 = wp::extract(var_11, var_12);
    var_14 = ggx_d_0(var_13, var_alpha);
    var_16 = wp::extract(var_11, var_15);
    var_17 = wp::mul(var_14, var_16);
    var_19 = wp::dot(var_wo, var_11);
    var_21 = wp::max(var_19, var_20);
    var_22 = wp::mul(var_18, var_21);
    var_23 = wp::div(var_17, var_22);
    return var_23;
}


// /work/main/simulator/kernels/bsdf.py:213
static wp::float32 bsdf_pdf_0(
    Bsdf_4cf4d8bd var_b,
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo)
{
    //---------
    // primal vars
    bool var_0;
    const wp::int32 var_1 = 2;
    wp::float32 var_2;
    const wp::float32 var_3 = 0.0;
    bool var_4;
    const wp::int32 var_5 = 2;
    wp::float32 var_6;
    const wp::float32 var_7 = 0.0;
    bool var_8;
    const wp::float32 var_9 = 0.0;
    const wp::int32 var_10 = 2;
    wp::float32 var_11;
    wp::vec_t<3, wp::float32> var_12;
    const wp::int32 var_13 = 2;
    wp::float32 var_14;
    const wp::int32 var_15 = 2;
    wp::float32 var_16;
    wp::float32 var_17;
    const wp::float32 var_18 = 0.318309886183791;
    wp::float32 var_19;
    const wp::int32 var_20 = 0;
    wp::float32 var_21;
    const wp::float32 var_22 = 0.0;
    bool var_23;
    const wp::int32 var_24 = 0;
    wp::float32 var_25;
    wp::float32* var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    const wp::int32 var_32 = 1;
    wp::float32 var_33;
    const wp::float32 var_34 = 0.0;
    bool var_35;
    const wp::int32 var_36 = 1;
    wp::float32 var_37;
    wp::float32* var_38;
    wp::float32 var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    //---------
    // forward
    // def bsdf_pdf(b: Bsdf, wi: wp.vec3, wo: wp.vec3) -> float:                              <L 214>
    // if wi[2] <= 0.0 or wo[2] <= 0.0:                                                       <L 216>
    var_2 = wp::extract(var_wi, var_1);
    var_4 = (var_2 <= var_3);
    var_0 = var_4;
    if (!var_0) {
        var_6 = wp::extract(var_wo, var_5);
        var_8 = (var_6 <= var_7);
        var_0 = var_0 || var_8;
    }
    if (var_0) {
        // return 0.0                                                                         <L 217>
        return var_9;
    }
    // p = lobe_weights(b, wo[2])                                                             <L 218>
    var_11 = wp::extract(var_wo, var_10);
    var_12 = lobe_weights_0(var_b, var_11);
    // pdf = p[2] * wi[2] * INV_PI_B                                                          <L 219>
    var_14 = wp::extract(var_12, var_13);
    var_16 = wp::extract(var_wi, var_15);
    var_17 = wp::mul(var_14, var_16);
    var_19 = wp::mul(var_17, var_18);
    // if p[0] > 0.0:                                                                         <L 220>
    var_21 = wp::extract(var_12, var_20);
    var_23 = (var_21 > var_22);
    if (var_23) {
        // pdf += p[0] * microfacet_pdf(wi, wo, b.coat_alpha)                                 <L 221>
        var_25 = wp::extract(var_12, var_24);
        var_26 = &((var_b).coat_alpha);
        var_28 = wp::load(var_26);
        var_27 = microfacet_pdf_0(var_wi, var_wo, var_28);
        var_29 = wp::mul(var_25, var_27);
        var_30 = wp::add(var_19, var_29);
    }
    var_31 = wp::where(var_23, var_30, var_19);
    // if p[1] > 0.0:                                                                         <L 222>
    var_33 = wp::extract(var_12, var_32);
    var_35 = (var_33 > var_34);
    if (var_35) {
        // pdf += p[1] * microfacet_pdf(wi, wo, b.alpha)                                      <L 223>
        var_37 = wp::extract(var_12, var_36);
        var_38 = &((var_b).alpha);
        var_40 = wp::load(var_38);
        var_39 = microfacet_pdf_0(var_wi, var_wo, var_40);
        var_41 = wp::mul(var_37, var_39);
        var_42 = wp::add(var_31, var_41);
    }
    var_43 = wp::where(var_35, var_42, var_31);
    // return pdf                                                                             <L 224>
    return var_43;
}


// /work/main/simulator/kernels/bsdf.py:134
static wp::vec_t<3, wp::float32> microfacet_sample_0(
    wp::vec_t<3, wp::float32> var_wo,
    wp::float32 var_alpha,
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::float32 var_0;
    const wp::int32 var_1 = 0;
    wp::float32 var_2;
    wp::float32 var_3;
    const wp::float32 var_4 = 1.0;
    const wp::int32 var_5 = 0;
    wp::float32 var_6;
    wp::float32 var_7;
    const wp::float32 var_8 = 1e-12;
    wp::float32 var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 1.0;
    const wp::float32 var_12 = 1.0;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    const wp::float32 var_16 = 0.0;
    const wp::float32 var_17 = 1.0;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    const wp::float32 var_22 = 2.0;
    const wp::float32 var_23 = 3.14159265358979;
    wp::float32 var_24;
    const wp::int32 var_25 = 1;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::vec_t<3, wp::float32> var_32;
    const wp::float32 var_33 = 2.0;
    wp::float32 var_34;
    wp::float32 var_35;
    wp::vec_t<3, wp::float32> var_36;
    wp::vec_t<3, wp::float32> var_37;
    //---------
    // forward
    // def microfacet_sample(wo: wp.vec3, alpha: float, u: wp.vec2) -> wp.vec3:               <L 135>
    // t2 = alpha * alpha * u[0] / wp.max(1.0 - u[0], 1.0e-12)                                <L 138>
    var_0 = wp::mul(var_alpha, var_alpha);
    var_2 = wp::extract(var_u, var_1);
    var_3 = wp::mul(var_0, var_2);
    var_6 = wp::extract(var_u, var_5);
    var_7 = wp::sub(var_4, var_6);
    var_9 = wp::max(var_7, var_8);
    var_10 = wp::div(var_3, var_9);
    // ch = 1.0 / wp.sqrt(1.0 + t2)                                                           <L 139>
    var_13 = wp::add(var_12, var_10);
    var_14 = wp::sqrt(var_13);
    var_15 = wp::div(var_11, var_14);
    // sh = wp.sqrt(wp.max(0.0, 1.0 - ch * ch))                                               <L 140>
    var_18 = wp::mul(var_15, var_15);
    var_19 = wp::sub(var_17, var_18);
    var_20 = wp::max(var_16, var_19);
    var_21 = wp::sqrt(var_20);
    // phi = 2.0 * PI_B * u[1]                                                                <L 141>
    var_24 = wp::mul(var_22, var_23);
    var_26 = wp::extract(var_u, var_25);
    var_27 = wp::mul(var_24, var_26);
    // h = wp.vec3(sh * wp.cos(phi), sh * wp.sin(phi), ch)                                    <L 142>
    var_28 = wp::cos(var_27);
    var_29 = wp::mul(var_21, var_28);
    var_30 = wp::sin(var_27);
    var_31 = wp::mul(var_21, var_30);
    var_32 = wp::vec_t<3, wp::float32>(var_29, var_31, var_15);
    // return (2.0 * wp.dot(wo, h)) * h - wo                                                  <L 143>
    var_34 = wp::dot(var_wo, var_32);
    var_35 = wp::mul(var_33, var_34);
    var_36 = wp::mul(var_35, var_32);
    var_37 = wp::sub(var_36, var_wo);
    return var_37;
}


// /work/main/simulator/kernels/bsdf.py:227
static wp::vec_t<3, wp::float32> bsdf_sample_0(
    Bsdf_4cf4d8bd var_b,
    wp::vec_t<3, wp::float32> var_wo,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    wp::vec_t<3, wp::float32> var_2;
    const wp::int32 var_3 = 1;
    wp::float32 var_4;
    const wp::int32 var_5 = 2;
    wp::float32 var_6;
    wp::vec_t<2, wp::float32> var_7;
    const wp::int32 var_8 = 0;
    wp::float32 var_9;
    const wp::int32 var_10 = 0;
    wp::float32 var_11;
    bool var_12;
    wp::float32* var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::float32 var_15;
    const wp::int32 var_16 = 0;
    wp::float32 var_17;
    const wp::int32 var_18 = 0;
    wp::float32 var_19;
    const wp::int32 var_20 = 1;
    wp::float32 var_21;
    wp::float32 var_22;
    bool var_23;
    wp::float32* var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::float32 var_26;
    const wp::int32 var_27 = 0;
    wp::float32 var_28;
    wp::float32 var_29;
    const wp::float32 var_30 = 2.0;
    const wp::float32 var_31 = 3.14159265358979;
    wp::float32 var_32;
    const wp::int32 var_33 = 1;
    wp::float32 var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::float32 var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    const wp::float32 var_40 = 0.0;
    const wp::float32 var_41 = 1.0;
    const wp::int32 var_42 = 0;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32 var_45;
    wp::float32 var_46;
    wp::vec_t<3, wp::float32> var_47;
    //---------
    // forward
    // def bsdf_sample(b: Bsdf, wo: wp.vec3, u: wp.vec3) -> wp.vec3:                          <L 228>
    // p = lobe_weights(b, wo[2])                                                             <L 231>
    var_1 = wp::extract(var_wo, var_0);
    var_2 = lobe_weights_0(var_b, var_1);
    // v = wp.vec2(u[1], u[2])                                                                <L 232>
    var_4 = wp::extract(var_u, var_3);
    var_6 = wp::extract(var_u, var_5);
    var_7 = wp::vec_t<2, wp::float32>(var_4, var_6);
    // if u[0] < p[0]:                                                                        <L 233>
    var_9 = wp::extract(var_u, var_8);
    var_11 = wp::extract(var_2, var_10);
    var_12 = (var_9 < var_11);
    if (var_12) {
        // return microfacet_sample(wo, b.coat_alpha, v)                                      <L 234>
        var_13 = &((var_b).coat_alpha);
        var_15 = wp::load(var_13);
        var_14 = microfacet_sample_0(var_wo, var_15, var_7);
        return var_14;
    }
    // if u[0] < p[0] + p[1]:                                                                 <L 235>
    var_17 = wp::extract(var_u, var_16);
    var_19 = wp::extract(var_2, var_18);
    var_21 = wp::extract(var_2, var_20);
    var_22 = wp::add(var_19, var_21);
    var_23 = (var_17 < var_22);
    if (var_23) {
        // return microfacet_sample(wo, b.alpha, v)                                           <L 236>
        var_24 = &((var_b).alpha);
        var_26 = wp::load(var_24);
        var_25 = microfacet_sample_0(var_wo, var_26, var_7);
        return var_25;
    }
    // r = wp.sqrt(v[0])                                                                      <L 237>
    var_28 = wp::extract(var_7, var_27);
    var_29 = wp::sqrt(var_28);
    // phi = 2.0 * PI_B * v[1]                                                                <L 238>
    var_32 = wp::mul(var_30, var_31);
    var_34 = wp::extract(var_7, var_33);
    var_35 = wp::mul(var_32, var_34);
    // return wp.vec3(r * wp.cos(phi), r * wp.sin(phi), wp.sqrt(wp.max(0.0, 1.0 - v[0])))       <L 239>
    var_36 = wp::cos(var_35);
    var_37 = wp::mul(var_29, var_36);
    var_38 = wp::sin(var_35);
    var_39 = wp::mul(var_29, var_38);
    var_43 = wp::extract(var_7, var_42);
    var_44 = wp::sub(var_41, var_43);
    var_45 = wp::max(var_40, var_44);
    var_46 = wp::sqrt(var_45);
    var_47 = wp::vec_t<3, wp::float32>(var_37, var_39, var_46);
    return var_47;
}


// /work/main/simulator/kernels/bsdf.py:63
static void adj_preview_bsdf_0(
    wp::float32 var_rho,
    wp::float32 var_roughness,
    wp::float32 var_metallic,
    wp::float32 var_ior,
    wp::float32 var_specular,
    wp::int32 var_workflow,
    wp::float32 var_coat,
    wp::float32 var_coat_roughness,
    wp::float32 & adj_rho,
    wp::float32 & adj_roughness,
    wp::float32 & adj_metallic,
    wp::float32 & adj_ior,
    wp::float32 & adj_specular,
    wp::int32 & adj_workflow,
    wp::float32 & adj_coat,
    wp::float32 & adj_coat_roughness,
    Bsdf_4cf4d8bd & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/tests/test_bsdf.py:33
static void adj__lobes_0(
    wp::vec_t<4, wp::float32> var_p,
    wp::vec_t<4, wp::float32> var_q,
    wp::vec_t<4, wp::float32> & adj_p,
    wp::vec_t<4, wp::float32> & adj_q,
    Bsdf_4cf4d8bd & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:84
static void adj_schlick_0(
    wp::float32 var_f0,
    wp::float32 var_f90,
    wp::float32 var_c,
    wp::float32 & adj_f0,
    wp::float32 & adj_f90,
    wp::float32 & adj_c,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:170
static void adj_diffuse_f_0(
    Bsdf_4cf4d8bd var_b,
    wp::float32 var_ci,
    wp::float32 var_co,
    Bsdf_4cf4d8bd & adj_b,
    wp::float32 & adj_ci,
    wp::float32 & adj_co,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:146
static void adj_is_delta_specular_0(
    Bsdf_4cf4d8bd var_b,
    Bsdf_4cf4d8bd & adj_b,
    bool & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:92
static void adj_ggx_d_0(
    wp::float32 var_cos_h,
    wp::float32 var_alpha,
    wp::float32 & adj_cos_h,
    wp::float32 & adj_alpha,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:100
static void adj_ggx_lambda_0(
    wp::float32 var_c,
    wp::float32 var_alpha,
    wp::float32 & adj_c,
    wp::float32 & adj_alpha,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:108
static void adj_ggx_g2_0(
    wp::float32 var_ci,
    wp::float32 var_co,
    wp::float32 var_alpha,
    wp::float32 & adj_ci,
    wp::float32 & adj_co,
    wp::float32 & adj_alpha,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:114
static void adj_microfacet_f_0(
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo,
    wp::float32 var_alpha,
    wp::float32 var_f0,
    wp::float32 var_f90,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::vec_t<3, wp::float32> & adj_wo,
    wp::float32 & adj_alpha,
    wp::float32 & adj_f0,
    wp::float32 & adj_f90,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:164
static void adj_coat_factor_0(
    Bsdf_4cf4d8bd var_b,
    wp::float32 var_c,
    Bsdf_4cf4d8bd & adj_b,
    wp::float32 & adj_c,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:152
static void adj_is_delta_coat_0(
    Bsdf_4cf4d8bd var_b,
    Bsdf_4cf4d8bd & adj_b,
    bool & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:176
static void adj_bsdf_f_0(
    Bsdf_4cf4d8bd var_b,
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo,
    Bsdf_4cf4d8bd & adj_b,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::vec_t<3, wp::float32> & adj_wo,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:195
static void adj_lobe_weights_0(
    Bsdf_4cf4d8bd var_b,
    wp::float32 var_co,
    Bsdf_4cf4d8bd & adj_b,
    wp::float32 & adj_co,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:125
static void adj_microfacet_pdf_0(
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo,
    wp::float32 var_alpha,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::vec_t<3, wp::float32> & adj_wo,
    wp::float32 & adj_alpha,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:213
static void adj_bsdf_pdf_0(
    Bsdf_4cf4d8bd var_b,
    wp::vec_t<3, wp::float32> var_wi,
    wp::vec_t<3, wp::float32> var_wo,
    Bsdf_4cf4d8bd & adj_b,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::vec_t<3, wp::float32> & adj_wo,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:134
static void adj_microfacet_sample_0(
    wp::vec_t<3, wp::float32> var_wo,
    wp::float32 var_alpha,
    wp::vec_t<2, wp::float32> var_u,
    wp::vec_t<3, wp::float32> & adj_wo,
    wp::float32 & adj_alpha,
    wp::vec_t<2, wp::float32> & adj_u,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/bsdf.py:227
static void adj_bsdf_sample_0(
    Bsdf_4cf4d8bd var_b,
    wp::vec_t<3, wp::float32> var_wo,
    wp::vec_t<3, wp::float32> var_u,
    Bsdf_4cf4d8bd & adj_b,
    wp::vec_t<3, wp::float32> & adj_wo,
    wp::vec_t<3, wp::float32> & adj_u,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}

struct wp_args_k_eval_8bd37771 {
    wp::vec_t<4, wp::float32> p;
    wp::vec_t<4, wp::float32> q;
    wp::array_t<wp::vec_t<3, wp::float32>> wi;
    wp::array_t<wp::vec_t<3, wp::float32>> wo;
    wp::array_t<wp::float32> f;
    wp::array_t<wp::float32> pdf;
};


template <bool wp_linear_contiguous>
static void k_eval_8bd37771_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_eval_8bd37771 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_eval_8bd37771 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.wi.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.wo.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.f.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::vec_t<4, wp::float32> var_p = _wp_args->p;
    wp::vec_t<4, wp::float32> var_q = _wp_args->q;
    wp::array_t<wp::vec_t<3, wp::float32>> var_wi = _wp_args->wi;
    wp::array_t<wp::vec_t<3, wp::float32>> var_wo = _wp_args->wo;
    wp::array_t<wp::float32> var_f = _wp_args->f;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    //---------
    // primal vars
    wp::int32 var_0;
    Bsdf_4cf4d8bd var_1;
    wp::vec_t<3, wp::float32>* var_2;
    wp::vec_t<3, wp::float32>* var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32>* var_7;
    wp::vec_t<3, wp::float32>* var_8;
    wp::float32 var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<3, wp::float32> var_11;
    //---------
    // forward
    // def k_eval(p: wp.vec4, q: wp.vec4, wi: wp.array(dtype=wp.vec3), wo: wp.array(dtype=wp.vec3),       <L 59>
    // i = wp.tid()                                                                           <L 61>
    var_0 = builtin_tid1d();
    // b = _lobes(p, q)                                                                       <L 62>
    var_1 = _lobes_0(var_p, var_q);
    // f[i] = bsdf_f(b, wi[i], wo[i])                                                         <L 63>
    var_2 = wp::address(var_wi, var_0);
    var_3 = wp::address(var_wo, var_0);
    var_5 = wp::load(var_2);
    var_6 = wp::load(var_3);
    var_4 = bsdf_f_0(var_1, var_5, var_6);
    wp::array_store(var_f, var_0, var_4);
    // pdf[i] = bsdf_pdf(b, wi[i], wo[i])                                                     <L 64>
    var_7 = wp::address(var_wi, var_0);
    var_8 = wp::address(var_wo, var_0);
    var_10 = wp::load(var_7);
    var_11 = wp::load(var_8);
    var_9 = bsdf_pdf_0(var_1, var_10, var_11);
    wp::array_store(var_pdf, var_0, var_9);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_eval_8bd37771_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_eval_8bd37771 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_eval_8bd37771_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_eval_8bd37771_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_eval_8bd37771 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->wi.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->wo.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->f.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_eval_8bd37771_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_eval_8bd37771_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_eval_8bd37771_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_eval_8bd37771 *_wp_args)
{
    k_eval_8bd37771_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_sample_8f9eadae {
    wp::int32 seed;
    wp::vec_t<4, wp::float32> p;
    wp::vec_t<4, wp::float32> q;
    wp::vec_t<3, wp::float32> wo;
    wp::array_t<wp::vec_t<3, wp::float32>> out;
    wp::array_t<wp::float32> pdf;
    wp::array_t<wp::float32> weight;
};


template <bool wp_linear_contiguous>
static void k_sample_8f9eadae_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_sample_8f9eadae *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_sample_8f9eadae wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.out.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.weight.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::int32 var_seed = _wp_args->seed;
    wp::vec_t<4, wp::float32> var_p = _wp_args->p;
    wp::vec_t<4, wp::float32> var_q = _wp_args->q;
    wp::vec_t<3, wp::float32> var_wo = _wp_args->wo;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out = _wp_args->out;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    wp::array_t<wp::float32> var_weight = _wp_args->weight;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    Bsdf_4cf4d8bd var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.0;
    wp::float32 var_10;
    bool var_11;
    const wp::int32 var_12 = 2;
    wp::float32 var_13;
    const wp::float32 var_14 = 0.0;
    bool var_15;
    const wp::float32 var_16 = 0.0;
    bool var_17;
    wp::float32 var_18;
    const wp::int32 var_19 = 2;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    //---------
    // forward
    // def k_sample(seed: int, p: wp.vec4, q: wp.vec4, wo: wp.vec3, out: wp.array(dtype=wp.vec3),       <L 43>
    // i = wp.tid()                                                                           <L 45>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 46>
    var_1 = wp::rand_init(var_seed, var_0);
    // b = _lobes(p, q)                                                                       <L 47>
    var_2 = _lobes_0(var_p, var_q);
    // wi = bsdf_sample(b, wo, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))          <L 48>
    var_3 = wp::randf(var_1);
    var_4 = wp::randf(var_1);
    var_5 = wp::randf(var_1);
    var_6 = wp::vec_t<3, wp::float32>(var_3, var_4, var_5);
    var_7 = bsdf_sample_0(var_2, var_wo, var_6);
    // out[i] = wi                                                                            <L 49>
    wp::array_store(var_out, var_0, var_7);
    // pr = bsdf_pdf(b, wi, wo)                                                               <L 50>
    var_8 = bsdf_pdf_0(var_2, var_7, var_wo);
    // pdf[i] = pr                                                                            <L 51>
    wp::array_store(var_pdf, var_0, var_8);
    // w = float(0.0)                                                                         <L 52>
    var_10 = wp::float(var_9);
    // if wi[2] > 0.0 and pr > 0.0:                                                           <L 53>
    var_13 = wp::extract(var_7, var_12);
    var_15 = (var_13 > var_14);
    var_11 = var_15;
    if (var_11) {
        var_17 = (var_8 > var_16);
        var_11 = var_11 && var_17;
    }
    if (var_11) {
        // w = bsdf_f(b, wi, wo) * wi[2] / pr                                                 <L 54>
        var_18 = bsdf_f_0(var_2, var_7, var_wo);
        var_20 = wp::extract(var_7, var_19);
        var_21 = wp::mul(var_18, var_20);
        var_22 = wp::div(var_21, var_8);
    }
    var_23 = wp::where(var_11, var_22, var_10);
    // weight[i] = w                                                                          <L 55>
    wp::array_store(var_weight, var_0, var_23);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_sample_8f9eadae_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sample_8f9eadae *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_sample_8f9eadae_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_sample_8f9eadae_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sample_8f9eadae *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->out.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->weight.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_sample_8f9eadae_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_sample_8f9eadae_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_sample_8f9eadae_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sample_8f9eadae *_wp_args)
{
    k_sample_8f9eadae_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

