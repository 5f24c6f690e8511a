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


struct Dist2DSample_164324b3
{
    wp::vec_t<2, wp::float32> uv;
    wp::float32 pdf;
    wp::int32 texel;


    Dist2DSample_164324b3() = default;
    CUDA_CALLABLE Dist2DSample_164324b3(wp::vec_t<2, wp::float32> const& uv,
    wp::float32 const& pdf = {},
    wp::int32 const& texel = {})
        : uv{uv}
        , pdf{pdf}
        , texel{texel}

    {
    }

    CUDA_CALLABLE Dist2DSample_164324b3& operator += (const Dist2DSample_164324b3& rhs)
    {    uv += rhs.uv;
    pdf += rhs.pdf;
    texel += rhs.texel;

        return *this;}

};

static CUDA_CALLABLE void adj_Dist2DSample_164324b3(wp::vec_t<2, wp::float32> const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::vec_t<2, wp::float32> & adj_uv,
    wp::float32 & adj_pdf,
    wp::int32 & adj_texel,
    Dist2DSample_164324b3 & adj_ret)
{
    adj_uv += adj_ret.uv;
    adj_pdf += adj_ret.pdf;
    adj_texel += adj_ret.texel;
}

// Required when compiling adjoints.
CUDA_CALLABLE Dist2DSample_164324b3 add(const Dist2DSample_164324b3& a, const Dist2DSample_164324b3& b)
{
    return Dist2DSample_164324b3();
}

CUDA_CALLABLE void adj_atomic_add(Dist2DSample_164324b3* p, Dist2DSample_164324b3 t)
{
    wp::adj_atomic_add(&p->uv, t.uv);
    wp::adj_atomic_add(&p->pdf, t.pdf);
    wp::adj_atomic_add(&p->texel, t.texel);
}




struct LatLongSample_6aa5dbc2
{
    wp::vec_t<3, wp::float32> wi;
    wp::float32 pdf;
    wp::int32 texel;


    LatLongSample_6aa5dbc2() = default;
    CUDA_CALLABLE LatLongSample_6aa5dbc2(wp::vec_t<3, wp::float32> const& wi,
    wp::float32 const& pdf = {},
    wp::int32 const& texel = {})
        : wi{wi}
        , pdf{pdf}
        , texel{texel}

    {
    }

    CUDA_CALLABLE LatLongSample_6aa5dbc2& operator += (const LatLongSample_6aa5dbc2& rhs)
    {    wi += rhs.wi;
    pdf += rhs.pdf;
    texel += rhs.texel;

        return *this;}

};

static CUDA_CALLABLE void adj_LatLongSample_6aa5dbc2(wp::vec_t<3, wp::float32> const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_pdf,
    wp::int32 & adj_texel,
    LatLongSample_6aa5dbc2 & adj_ret)
{
    adj_wi += adj_ret.wi;
    adj_pdf += adj_ret.pdf;
    adj_texel += adj_ret.texel;
}

// Required when compiling adjoints.
CUDA_CALLABLE LatLongSample_6aa5dbc2 add(const LatLongSample_6aa5dbc2& a, const LatLongSample_6aa5dbc2& b)
{
    return LatLongSample_6aa5dbc2();
}

CUDA_CALLABLE void adj_atomic_add(LatLongSample_6aa5dbc2* p, LatLongSample_6aa5dbc2 t)
{
    wp::adj_atomic_add(&p->wi, t.wi);
    wp::adj_atomic_add(&p->pdf, t.pdf);
    wp::adj_atomic_add(&p->texel, t.texel);
}




// /work/main/simulator/kernels/distributions.py:53
static wp::int32 cdf_interval_0(
    wp::array_t<wp::float32> var_cdf,
    wp::int32 var_start,
    wp::int32 var_n,
    wp::float32 var_u)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::int32 var_1;
    const wp::int32 var_2 = 1;
    wp::int32 var_3;
    bool var_4;
    wp::int32 var_5;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    const wp::int32 var_8 = 2;
    wp::int32 var_9;
    wp::int32 var_10;
    wp::float32* var_11;
    bool var_12;
    wp::float32 var_13;
    wp::int32 var_14;
    const wp::int32 var_15 = 1;
    wp::int32 var_16;
    wp::int32 var_17;
    wp::int32 var_18;
    //---------
    // forward
    // def cdf_interval(cdf: wp.array(dtype=float), start: int, n: int, u: float) -> int:       <L 54>
    // lo = int(0)                                                                            <L 59>
    var_1 = wp::int(var_0);
    // hi = n - 1                                                                             <L 60>
    var_3 = wp::sub(var_n, var_2);
    // while lo < hi:                                                                         <L 61>
    start_while_0:;
    var_4 = (var_1 < var_3);
    if ((var_4) == false) goto end_while_0;
        // mid = (lo + hi + 1) // 2                                                           <L 62>
        var_5 = wp::add(var_1, var_3);
        var_7 = wp::add(var_5, var_6);
        var_9 = wp::floordiv(var_7, var_8);
        // if cdf[start + mid] <= u:                                                          <L 63>
        var_10 = wp::add(var_start, var_9);
        var_11 = wp::address(var_cdf, var_10);
        var_13 = wp::load(var_11);
        var_12 = (var_13 <= var_u);
        if (var_12) {
            // lo = mid                                                                       <L 64>
            var_14 = wp::copy(var_9);
        }
        if (!var_12) {
            // hi = mid - 1                                                                   <L 66>
            var_16 = wp::sub(var_9, var_15);
        }
        var_17 = wp::where(var_12, var_14, var_1);
        var_18 = wp::where(var_12, var_3, var_16);
        wp::assign(var_1, var_17);
        wp::assign(var_3, var_18);
    goto start_while_0;
    end_while_0:;
    // return lo                                                                              <L 67>
    return var_1;
}


// /work/main/simulator/kernels/distributions.py:70
static Dist2DSample_164324b3 sample_piecewise_2d_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    Dist2DSample_164324b3 var_0;
    const wp::int32 var_1 = 0;
    wp::float32 var_2;
    const wp::float32 var_3 = 0.0;
    wp::float32 var_4;
    const wp::float32 var_5 = 0.99999994;
    wp::float32 var_6;
    const wp::int32 var_7 = 1;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.0;
    wp::float32 var_10;
    wp::float32 var_11;
    const wp::int32 var_12 = 0;
    wp::int32 var_13;
    const wp::int32 var_14 = 1;
    wp::int32 var_15;
    wp::float32* var_16;
    wp::float32* var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    const wp::int32 var_21 = 1;
    wp::int32 var_22;
    wp::int32 var_23;
    wp::int32 var_24;
    wp::int32 var_25;
    const wp::int32 var_26 = 1;
    wp::int32 var_27;
    wp::float32* var_28;
    wp::int32 var_29;
    wp::float32* var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32 var_33;
    wp::float32* var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 0.0;
    wp::float32 var_39;
    wp::int32 var_40;
    wp::float32* var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    const wp::float32 var_45 = 0.0;
    wp::float32 var_46;
    wp::float32 var_47;
    wp::float32 var_48;
    wp::float32 var_49;
    wp::float32 var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::vec_t<2, wp::float32> var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32 var_58;
    wp::float32 var_59;
    wp::float32 var_60;
    wp::int32 var_61;
    wp::int32 var_62;
    //---------
    // forward
    // def sample_piecewise_2d(                                                               <L 71>
    // s = Dist2DSample()                                                                     <L 76>
    var_0 = Dist2DSample_164324b3();
    // u0 = wp.min(wp.max(u[0], 0.0), ONE_MINUS_EPS)                                          <L 77>
    var_2 = wp::extract(var_u, var_1);
    var_4 = wp::max(var_2, var_3);
    var_6 = wp::min(var_4, var_5);
    // u1 = wp.min(wp.max(u[1], 0.0), ONE_MINUS_EPS)                                          <L 78>
    var_8 = wp::extract(var_u, var_7);
    var_10 = wp::max(var_8, var_9);
    var_11 = wp::min(var_10, var_5);
    // j = cdf_interval(marg, 0, h, u0)                                                       <L 79>
    var_13 = cdf_interval_0(var_marg, var_12, var_h, var_6);
    // pm = marg[j + 1] - marg[j]                                                             <L 80>
    var_15 = wp::add(var_13, var_14);
    var_16 = wp::address(var_marg, var_15);
    var_17 = wp::address(var_marg, var_13);
    var_19 = wp::load(var_16);
    var_20 = wp::load(var_17);
    var_18 = wp::sub(var_19, var_20);
    // row = j * (w + 1)                                                                      <L 81>
    var_22 = wp::add(var_w, var_21);
    var_23 = wp::mul(var_13, var_22);
    // i = cdf_interval(cond, row, w, u1)                                                     <L 82>
    var_24 = cdf_interval_0(var_cond, var_23, var_w, var_11);
    // pc = cond[row + i + 1] - cond[row + i]                                                 <L 83>
    var_25 = wp::add(var_23, var_24);
    var_27 = wp::add(var_25, var_26);
    var_28 = wp::address(var_cond, var_27);
    var_29 = wp::add(var_23, var_24);
    var_30 = wp::address(var_cond, var_29);
    var_32 = wp::load(var_28);
    var_33 = wp::load(var_30);
    var_31 = wp::sub(var_32, var_33);
    // fv = wp.clamp((u0 - marg[j]) / pm, 0.0, ONE_MINUS_EPS)                                 <L 84>
    var_34 = wp::address(var_marg, var_13);
    var_36 = wp::load(var_34);
    var_35 = wp::sub(var_6, var_36);
    var_37 = wp::div(var_35, var_18);
    var_39 = wp::clamp(var_37, var_38, var_5);
    // fu = wp.clamp((u1 - cond[row + i]) / pc, 0.0, ONE_MINUS_EPS)                           <L 85>
    var_40 = wp::add(var_23, var_24);
    var_41 = wp::address(var_cond, var_40);
    var_43 = wp::load(var_41);
    var_42 = wp::sub(var_11, var_43);
    var_44 = wp::div(var_42, var_31);
    var_46 = wp::clamp(var_44, var_45, var_5);
    // s.uv = wp.vec2((float(i) + fu) / float(w), (float(j) + fv) / float(h))                 <L 86>
    var_47 = wp::float(var_24);
    var_48 = wp::add(var_47, var_46);
    var_49 = wp::float(var_w);
    var_50 = wp::div(var_48, var_49);
    var_51 = wp::float(var_13);
    var_52 = wp::add(var_51, var_39);
    var_53 = wp::float(var_h);
    var_54 = wp::div(var_52, var_53);
    var_55 = wp::vec_t<2, wp::float32>(var_50, var_54);
    var_0.uv = var_55;
    // s.pdf = (float(h) * pm) * (float(w) * pc)                                              <L 87>
    var_56 = wp::float(var_h);
    var_57 = wp::mul(var_56, var_18);
    var_58 = wp::float(var_w);
    var_59 = wp::mul(var_58, var_31);
    var_60 = wp::mul(var_57, var_59);
    var_0.pdf = var_60;
    // s.texel = j * w + i                                                                    <L 88>
    var_61 = wp::mul(var_13, var_w);
    var_62 = wp::add(var_61, var_24);
    var_0.texel = var_62;
    // return s                                                                               <L 89>
    return var_0;
}


// /work/main/simulator/kernels/distributions.py:92
static wp::float32 pdf_piecewise_2d_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<2, wp::float32> var_uv)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::int32 var_4;
    const wp::int32 var_5 = 0;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    wp::int32 var_8;
    const wp::int32 var_9 = 1;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::int32 var_13;
    const wp::int32 var_14 = 0;
    const wp::int32 var_15 = 1;
    wp::int32 var_16;
    wp::int32 var_17;
    const wp::int32 var_18 = 1;
    wp::int32 var_19;
    wp::int32 var_20;
    wp::float32 var_21;
    const wp::int32 var_22 = 1;
    wp::int32 var_23;
    wp::float32* var_24;
    wp::float32* var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::int32 var_31;
    const wp::int32 var_32 = 1;
    wp::int32 var_33;
    wp::float32* var_34;
    wp::int32 var_35;
    wp::float32* var_36;
    wp::float32 var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    //---------
    // forward
    // def pdf_piecewise_2d(                                                                  <L 93>
    // i = wp.clamp(int(uv[0] * float(w)), 0, w - 1)                                          <L 97>
    var_1 = wp::extract(var_uv, var_0);
    var_2 = wp::float(var_w);
    var_3 = wp::mul(var_1, var_2);
    var_4 = wp::int(var_3);
    var_7 = wp::sub(var_w, var_6);
    var_8 = wp::clamp(var_4, var_5, var_7);
    // j = wp.clamp(int(uv[1] * float(h)), 0, h - 1)                                          <L 98>
    var_10 = wp::extract(var_uv, var_9);
    var_11 = wp::float(var_h);
    var_12 = wp::mul(var_10, var_11);
    var_13 = wp::int(var_12);
    var_16 = wp::sub(var_h, var_15);
    var_17 = wp::clamp(var_13, var_14, var_16);
    // row = j * (w + 1)                                                                      <L 99>
    var_19 = wp::add(var_w, var_18);
    var_20 = wp::mul(var_17, var_19);
    // return (float(h) * (marg[j + 1] - marg[j])) * (float(w) * (cond[row + i + 1] - cond[row + i]))       <L 100>
    var_21 = wp::float(var_h);
    var_23 = wp::add(var_17, var_22);
    var_24 = wp::address(var_marg, var_23);
    var_25 = wp::address(var_marg, var_17);
    var_27 = wp::load(var_24);
    var_28 = wp::load(var_25);
    var_26 = wp::sub(var_27, var_28);
    var_29 = wp::mul(var_21, var_26);
    var_30 = wp::float(var_w);
    var_31 = wp::add(var_20, var_8);
    var_33 = wp::add(var_31, var_32);
    var_34 = wp::address(var_cond, var_33);
    var_35 = wp::add(var_20, var_8);
    var_36 = wp::address(var_cond, var_35);
    var_38 = wp::load(var_34);
    var_39 = wp::load(var_36);
    var_37 = wp::sub(var_38, var_39);
    var_40 = wp::mul(var_30, var_37);
    var_41 = wp::mul(var_29, var_40);
    return var_41;
}


// /work/main/simulator/kernels/distributions.py:116
static wp::vec_t<2, wp::float32> direction_to_latlong_uv_0(
    wp::vec_t<3, wp::float32> var_d,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez)
{
    //---------
    // primal vars
    wp::float32 var_0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.5;
    const wp::float32 var_10 = 6.283185307179586;
    wp::float32 var_11;
    wp::float32 var_12;
    const wp::float32 var_13 = 3.141592653589793;
    wp::float32 var_14;
    wp::vec_t<2, wp::float32> var_15;
    //---------
    // forward
    // def direction_to_latlong_uv(d: wp.vec3, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec2:       <L 117>
    // lx = wp.dot(d, ex)                                                                     <L 120>
    var_0 = wp::dot(var_d, var_ex);
    // ly = wp.dot(d, ey)                                                                     <L 121>
    var_1 = wp::dot(var_d, var_ey);
    // lz = wp.dot(d, ez)                                                                     <L 122>
    var_2 = wp::dot(var_d, var_ez);
    // lon = wp.atan2(lx, lz)                                                                 <L 123>
    var_3 = wp::atan2(var_0, var_2);
    // theta = wp.atan2(wp.sqrt(lx * lx + lz * lz), ly)                                       <L 125>
    var_4 = wp::mul(var_0, var_0);
    var_5 = wp::mul(var_2, var_2);
    var_6 = wp::add(var_4, var_5);
    var_7 = wp::sqrt(var_6);
    var_8 = wp::atan2(var_7, var_1);
    // return wp.vec2(0.5 - lon / TWO_PI, theta / PI)                                         <L 126>
    var_11 = wp::div(var_3, var_10);
    var_12 = wp::sub(var_9, var_11);
    var_14 = wp::div(var_8, var_13);
    var_15 = wp::vec_t<2, wp::float32>(var_12, var_14);
    return var_15;
}


// /work/main/simulator/kernels/distributions.py:161
static wp::float32 pdf_latlong_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez,
    wp::vec_t<3, wp::float32> var_d)
{
    //---------
    // primal vars
    wp::float32 var_0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    const wp::float32 var_8 = 0.0;
    wp::vec_t<2, wp::float32> var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 19.739208802178716;
    wp::float32 var_12;
    wp::float32 var_13;
    //---------
    // forward
    // def pdf_latlong(                                                                       <L 162>
    // lx = wp.dot(d, ex)                                                                     <L 173>
    var_0 = wp::dot(var_d, var_ex);
    // lz = wp.dot(d, ez)                                                                     <L 174>
    var_1 = wp::dot(var_d, var_ez);
    // sin_t = wp.sqrt(lx * lx + lz * lz)                                                     <L 175>
    var_2 = wp::mul(var_0, var_0);
    var_3 = wp::mul(var_1, var_1);
    var_4 = wp::add(var_2, var_3);
    var_5 = wp::sqrt(var_4);
    // if sin_t <= 0.0:                                                                       <L 176>
    var_7 = (var_5 <= var_6);
    if (var_7) {
        // return 0.0                                                                         <L 177>
        return var_8;
    }
    // uv = direction_to_latlong_uv(d, ex, ey, ez)                                            <L 178>
    var_9 = direction_to_latlong_uv_0(var_d, var_ex, var_ey, var_ez);
    // return pdf_piecewise_2d(marg, cond, w, h, uv) / (TWO_PI_SQ * sin_t)                    <L 179>
    var_10 = pdf_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_9);
    var_12 = wp::mul(var_11, var_5);
    var_13 = wp::div(var_10, var_12);
    return var_13;
}


// /work/main/simulator/kernels/distributions.py:106
static wp::vec_t<3, wp::float32> latlong_uv_to_direction_0(
    wp::vec_t<2, wp::float32> var_uv,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 3.141592653589793;
    const wp::float32 var_1 = 1.0;
    const wp::float32 var_2 = 2.0;
    const wp::int32 var_3 = 0;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    const wp::int32 var_8 = 1;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::float32 var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    //---------
    // forward
    // def latlong_uv_to_direction(uv: wp.vec2, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec3:       <L 107>
    // lon = PI * (1.0 - 2.0 * uv[0])                                                         <L 110>
    var_4 = wp::extract(var_uv, var_3);
    var_5 = wp::mul(var_2, var_4);
    var_6 = wp::sub(var_1, var_5);
    var_7 = wp::mul(var_0, var_6);
    // theta = PI * uv[1]                                                                     <L 111>
    var_9 = wp::extract(var_uv, var_8);
    var_10 = wp::mul(var_0, var_9);
    // st = wp.sin(theta)                                                                     <L 112>
    var_11 = wp::sin(var_10);
    // return (st * wp.sin(lon)) * ex + wp.cos(theta) * ey + (st * wp.cos(lon)) * ez          <L 113>
    var_12 = wp::sin(var_7);
    var_13 = wp::mul(var_11, var_12);
    var_14 = wp::mul(var_13, var_ex);
    var_15 = wp::cos(var_10);
    var_16 = wp::mul(var_15, var_ey);
    var_17 = wp::add(var_14, var_16);
    var_18 = wp::cos(var_7);
    var_19 = wp::mul(var_11, var_18);
    var_20 = wp::mul(var_19, var_ez);
    var_21 = wp::add(var_17, var_20);
    return var_21;
}


// /work/main/simulator/kernels/distributions.py:137
static LatLongSample_6aa5dbc2 sample_latlong_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez,
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    Dist2DSample_164324b3 var_0;
    LatLongSample_6aa5dbc2 var_1;
    wp::vec_t<2, wp::float32>* var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::int32* var_5;
    wp::int32 var_6;
    wp::int32 var_7;
    const wp::float32 var_8 = 3.141592653589793;
    wp::vec_t<2, wp::float32>* var_9;
    const wp::int32 var_10 = 1;
    wp::float32 var_11;
    wp::vec_t<2, wp::float32> var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    const wp::float32 var_15 = 0.0;
    const wp::float32 var_16 = 0.0;
    bool var_17;
    wp::float32* var_18;
    const wp::float32 var_19 = 19.739208802178716;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    //---------
    // forward
    // def sample_latlong(                                                                    <L 138>
    // ds = sample_piecewise_2d(marg, cond, w, h, u)                                          <L 150>
    var_0 = sample_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_u);
    // s = LatLongSample()                                                                    <L 151>
    var_1 = LatLongSample_6aa5dbc2();
    // s.wi = latlong_uv_to_direction(ds.uv, ex, ey, ez)                                      <L 152>
    var_2 = &((var_0).uv);
    var_4 = wp::load(var_2);
    var_3 = latlong_uv_to_direction_0(var_4, var_ex, var_ey, var_ez);
    var_1.wi = var_3;
    // s.texel = ds.texel                                                                     <L 153>
    var_5 = &((var_0).texel);
    var_7 = wp::load(var_5);
    var_6 = wp::copy(var_7);
    var_1.texel = var_6;
    // sin_t = wp.sin(PI * ds.uv[1])                                                          <L 154>
    var_9 = &((var_0).uv);
    var_12 = wp::load(var_9);
    var_11 = wp::extract(var_12, var_10);
    var_13 = wp::mul(var_8, var_11);
    var_14 = wp::sin(var_13);
    // s.pdf = 0.0                                                                            <L 155>
    var_1.pdf = var_15;
    // if sin_t > 0.0:                                                                        <L 156>
    var_17 = (var_14 > var_16);
    if (var_17) {
        // s.pdf = ds.pdf / (TWO_PI_SQ * sin_t)                                               <L 157>
        var_18 = &((var_0).pdf);
        var_20 = wp::mul(var_19, var_14);
        var_22 = wp::load(var_18);
        var_21 = wp::div(var_22, var_20);
        var_1.pdf = var_21;
    }
    // return s                                                                               <L 158>
    return var_1;
}


// /work/main/simulator/kernels/distributions.py:53
static void adj_cdf_interval_0(
    wp::array_t<wp::float32> var_cdf,
    wp::int32 var_start,
    wp::int32 var_n,
    wp::float32 var_u,
    wp::array_t<wp::float32> & adj_cdf,
    wp::int32 & adj_start,
    wp::int32 & adj_n,
    wp::float32 & adj_u,
    wp::int32 & adj_ret)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::int32 var_1;
    const wp::int32 var_2 = 1;
    wp::int32 var_3;
    bool var_4;
    wp::int32 var_5;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    const wp::int32 var_8 = 2;
    wp::int32 var_9;
    wp::int32 var_10;
    wp::float32* var_11;
    bool var_12;
    wp::float32 var_13;
    wp::int32 var_14;
    const wp::int32 var_15 = 1;
    wp::int32 var_16;
    wp::int32 var_17;
    wp::int32 var_18;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::int32 adj_1 = {};
    wp::int32 adj_2 = {};
    wp::int32 adj_3 = {};
    bool adj_4 = {};
    wp::int32 adj_5 = {};
    wp::int32 adj_6 = {};
    wp::int32 adj_7 = {};
    wp::int32 adj_8 = {};
    wp::int32 adj_9 = {};
    wp::int32 adj_10 = {};
    wp::float32 adj_11 = {};
    bool adj_12 = {};
    wp::float32 adj_13 = {};
    wp::int32 adj_14 = {};
    wp::int32 adj_15 = {};
    wp::int32 adj_16 = {};
    wp::int32 adj_17 = {};
    wp::int32 adj_18 = {};
    //---------
    // forward
    // def cdf_interval(cdf: wp.array(dtype=float), start: int, n: int, u: float) -> int:       <L 54>
    // lo = int(0)                                                                            <L 59>
    var_1 = wp::int(var_0);
    // hi = n - 1                                                                             <L 60>
    var_3 = wp::sub(var_n, var_2);
    // while lo < hi:                                                                         <L 61>
    // return lo                                                                              <L 67>
    goto label2;
    //---------
    // reverse
    label2:;
    adj_1 += adj_ret;
    // adj: return lo                                                                         <L 67>
    start_while_0:;
    var_4 = (var_1 < var_3);
    if ((var_4) == false) goto end_while_0;
    adj_5 = {};
    adj_6 = {};
    adj_7 = {};
    adj_8 = {};
    adj_9 = {};
    adj_10 = {};
    adj_11 = {};
    adj_12 = {};
    adj_13 = {};
    adj_14 = {};
    adj_15 = {};
    adj_16 = {};
    adj_17 = {};
    adj_18 = {};
        // mid = (lo + hi + 1) // 2                                                           <L 62>
        var_5 = wp::add(var_1, var_3);
        var_7 = wp::add(var_5, var_6);
        var_9 = wp::floordiv(var_7, var_8);
        // if cdf[start + mid] <= u:                                                          <L 63>
        var_10 = wp::add(var_start, var_9);
        var_11 = wp::address(var_cdf, var_10);
        var_13 = wp::load(var_11);
        var_12 = (var_13 <= var_u);
        if (var_12) {
            // lo = mid                                                                       <L 64>
            var_14 = wp::copy(var_9);
        }
        if (!var_12) {
            // hi = mid - 1                                                                   <L 66>
            var_16 = wp::sub(var_9, var_15);
        }
        var_17 = wp::where(var_12, var_14, var_1);
        var_18 = wp::where(var_12, var_3, var_16);
        wp::assign(var_1, var_17);
        wp::assign(var_3, var_18);
        wp::adj_assign(var_3, var_18, adj_3, adj_18);
        wp::adj_assign(var_1, var_17, adj_1, adj_17);
        wp::adj_where(var_12, var_3, var_16, adj_12, adj_3, adj_16, adj_18);
        wp::adj_where(var_12, var_14, var_1, adj_12, adj_14, adj_1, adj_17);
        if (!var_12) {
            wp::adj_sub(var_9, var_15, adj_9, adj_15, adj_16);
            // adj: hi = mid - 1                                                              <L 66>
        }
        if (var_12) {
            wp::adj_copy(var_9, adj_9, adj_14);
            // adj: lo = mid                                                                  <L 64>
        }
        wp::adj_address(var_cdf, var_10, adj_cdf, adj_10, adj_11);
        wp::adj_add(var_start, var_9, adj_start, adj_9, adj_10);
        // adj: if cdf[start + mid] <= u:                                                     <L 63>
        wp::adj_add(var_5, var_6, adj_5, adj_6, adj_7);
        wp::adj_add(var_1, var_3, adj_1, adj_3, adj_5);
        // adj: mid = (lo + hi + 1) // 2                                                      <L 62>
    goto start_while_0;
    end_while_0:;
    // adj: while lo < hi:                                                                    <L 61>
    wp::adj_sub(var_n, var_2, adj_n, adj_2, adj_3);
    // adj: hi = n - 1                                                                        <L 60>
    // adj: lo = int(0)                                                                       <L 59>
    // adj: def cdf_interval(cdf: wp.array(dtype=float), start: int, n: int, u: float) -> int:  <L 54>
    return;
}


// /work/main/simulator/kernels/distributions.py:70
static void adj_sample_piecewise_2d_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<2, wp::float32> var_u,
    wp::array_t<wp::float32> & adj_marg,
    wp::array_t<wp::float32> & adj_cond,
    wp::int32 & adj_w,
    wp::int32 & adj_h,
    wp::vec_t<2, wp::float32> & adj_u,
    Dist2DSample_164324b3 & adj_ret)
{
    //---------
    // primal vars
    Dist2DSample_164324b3 var_0;
    const wp::int32 var_1 = 0;
    wp::float32 var_2;
    const wp::float32 var_3 = 0.0;
    wp::float32 var_4;
    const wp::float32 var_5 = 0.99999994;
    wp::float32 var_6;
    const wp::int32 var_7 = 1;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.0;
    wp::float32 var_10;
    wp::float32 var_11;
    const wp::int32 var_12 = 0;
    wp::int32 var_13;
    const wp::int32 var_14 = 1;
    wp::int32 var_15;
    wp::float32* var_16;
    wp::float32* var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    const wp::int32 var_21 = 1;
    wp::int32 var_22;
    wp::int32 var_23;
    wp::int32 var_24;
    wp::int32 var_25;
    const wp::int32 var_26 = 1;
    wp::int32 var_27;
    wp::float32* var_28;
    wp::int32 var_29;
    wp::float32* var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32 var_33;
    wp::float32* var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 0.0;
    wp::float32 var_39;
    wp::int32 var_40;
    wp::float32* var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    const wp::float32 var_45 = 0.0;
    wp::float32 var_46;
    wp::float32 var_47;
    wp::float32 var_48;
    wp::float32 var_49;
    wp::float32 var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::vec_t<2, wp::float32> var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32 var_58;
    wp::float32 var_59;
    wp::float32 var_60;
    wp::int32 var_61;
    wp::int32 var_62;
    //---------
    // dual vars
    Dist2DSample_164324b3 adj_0 = {};
    wp::int32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::float32 adj_4 = {};
    wp::float32 adj_5 = {};
    wp::float32 adj_6 = {};
    wp::int32 adj_7 = {};
    wp::float32 adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::int32 adj_12 = {};
    wp::int32 adj_13 = {};
    wp::int32 adj_14 = {};
    wp::int32 adj_15 = {};
    wp::float32 adj_16 = {};
    wp::float32 adj_17 = {};
    wp::float32 adj_18 = {};
    wp::float32 adj_19 = {};
    wp::float32 adj_20 = {};
    wp::int32 adj_21 = {};
    wp::int32 adj_22 = {};
    wp::int32 adj_23 = {};
    wp::int32 adj_24 = {};
    wp::int32 adj_25 = {};
    wp::int32 adj_26 = {};
    wp::int32 adj_27 = {};
    wp::float32 adj_28 = {};
    wp::int32 adj_29 = {};
    wp::float32 adj_30 = {};
    wp::float32 adj_31 = {};
    wp::float32 adj_32 = {};
    wp::float32 adj_33 = {};
    wp::float32 adj_34 = {};
    wp::float32 adj_35 = {};
    wp::float32 adj_36 = {};
    wp::float32 adj_37 = {};
    wp::float32 adj_38 = {};
    wp::float32 adj_39 = {};
    wp::int32 adj_40 = {};
    wp::float32 adj_41 = {};
    wp::float32 adj_42 = {};
    wp::float32 adj_43 = {};
    wp::float32 adj_44 = {};
    wp::float32 adj_45 = {};
    wp::float32 adj_46 = {};
    wp::float32 adj_47 = {};
    wp::float32 adj_48 = {};
    wp::float32 adj_49 = {};
    wp::float32 adj_50 = {};
    wp::float32 adj_51 = {};
    wp::float32 adj_52 = {};
    wp::float32 adj_53 = {};
    wp::float32 adj_54 = {};
    wp::vec_t<2, wp::float32> adj_55 = {};
    wp::float32 adj_56 = {};
    wp::float32 adj_57 = {};
    wp::float32 adj_58 = {};
    wp::float32 adj_59 = {};
    wp::float32 adj_60 = {};
    wp::int32 adj_61 = {};
    wp::int32 adj_62 = {};
    //---------
    // forward
    // def sample_piecewise_2d(                                                               <L 71>
    // s = Dist2DSample()                                                                     <L 76>
    var_0 = Dist2DSample_164324b3();
    // u0 = wp.min(wp.max(u[0], 0.0), ONE_MINUS_EPS)                                          <L 77>
    var_2 = wp::extract(var_u, var_1);
    var_4 = wp::max(var_2, var_3);
    var_6 = wp::min(var_4, var_5);
    // u1 = wp.min(wp.max(u[1], 0.0), ONE_MINUS_EPS)                                          <L 78>
    var_8 = wp::extract(var_u, var_7);
    var_10 = wp::max(var_8, var_9);
    var_11 = wp::min(var_10, var_5);
    // j = cdf_interval(marg, 0, h, u0)                                                       <L 79>
    var_13 = cdf_interval_0(var_marg, var_12, var_h, var_6);
    // pm = marg[j + 1] - marg[j]                                                             <L 80>
    var_15 = wp::add(var_13, var_14);
    var_16 = wp::address(var_marg, var_15);
    var_17 = wp::address(var_marg, var_13);
    var_19 = wp::load(var_16);
    var_20 = wp::load(var_17);
    var_18 = wp::sub(var_19, var_20);
    // row = j * (w + 1)                                                                      <L 81>
    var_22 = wp::add(var_w, var_21);
    var_23 = wp::mul(var_13, var_22);
    // i = cdf_interval(cond, row, w, u1)                                                     <L 82>
    var_24 = cdf_interval_0(var_cond, var_23, var_w, var_11);
    // pc = cond[row + i + 1] - cond[row + i]                                                 <L 83>
    var_25 = wp::add(var_23, var_24);
    var_27 = wp::add(var_25, var_26);
    var_28 = wp::address(var_cond, var_27);
    var_29 = wp::add(var_23, var_24);
    var_30 = wp::address(var_cond, var_29);
    var_32 = wp::load(var_28);
    var_33 = wp::load(var_30);
    var_31 = wp::sub(var_32, var_33);
    // fv = wp.clamp((u0 - marg[j]) / pm, 0.0, ONE_MINUS_EPS)                                 <L 84>
    var_34 = wp::address(var_marg, var_13);
    var_36 = wp::load(var_34);
    var_35 = wp::sub(var_6, var_36);
    var_37 = wp::div(var_35, var_18);
    var_39 = wp::clamp(var_37, var_38, var_5);
    // fu = wp.clamp((u1 - cond[row + i]) / pc, 0.0, ONE_MINUS_EPS)                           <L 85>
    var_40 = wp::add(var_23, var_24);
    var_41 = wp::address(var_cond, var_40);
    var_43 = wp::load(var_41);
    var_42 = wp::sub(var_11, var_43);
    var_44 = wp::div(var_42, var_31);
    var_46 = wp::clamp(var_44, var_45, var_5);
    // s.uv = wp.vec2((float(i) + fu) / float(w), (float(j) + fv) / float(h))                 <L 86>
    var_47 = wp::float(var_24);
    var_48 = wp::add(var_47, var_46);
    var_49 = wp::float(var_w);
    var_50 = wp::div(var_48, var_49);
    var_51 = wp::float(var_13);
    var_52 = wp::add(var_51, var_39);
    var_53 = wp::float(var_h);
    var_54 = wp::div(var_52, var_53);
    var_55 = wp::vec_t<2, wp::float32>(var_50, var_54);
    var_0.uv = var_55;
    // s.pdf = (float(h) * pm) * (float(w) * pc)                                              <L 87>
    var_56 = wp::float(var_h);
    var_57 = wp::mul(var_56, var_18);
    var_58 = wp::float(var_w);
    var_59 = wp::mul(var_58, var_31);
    var_60 = wp::mul(var_57, var_59);
    var_0.pdf = var_60;
    // s.texel = j * w + i                                                                    <L 88>
    var_61 = wp::mul(var_13, var_w);
    var_62 = wp::add(var_61, var_24);
    var_0.texel = var_62;
    // return s                                                                               <L 89>
    goto label0;
    //---------
    // reverse
    label0:;
    adj_0 += adj_ret;
    // adj: return s                                                                          <L 89>
    adj_0.texel = {};
    wp::adj_add(var_61, var_24, adj_61, adj_24, adj_62);
    wp::adj_mul(var_13, var_w, adj_13, adj_w, adj_61);
    // adj: s.texel = j * w + i                                                               <L 88>
    adj_60 += adj_0.pdf;
    adj_0.pdf = {};
    wp::adj_mul(var_57, var_59, adj_57, adj_59, adj_60);
    wp::adj_mul(var_58, var_31, adj_58, adj_31, adj_59);
    wp::adj_float(var_w, adj_w, adj_58);
    wp::adj_mul(var_56, var_18, adj_56, adj_18, adj_57);
    wp::adj_float(var_h, adj_h, adj_56);
    // adj: s.pdf = (float(h) * pm) * (float(w) * pc)                                         <L 87>
    adj_55 += adj_0.uv;
    adj_0.uv = {};
    wp::adj_vec_t(var_50, var_54, adj_50, adj_54, adj_55);
    wp::adj_div(var_52, var_53, var_54, adj_52, adj_53, adj_54);
    wp::adj_float(var_h, adj_h, adj_53);
    wp::adj_add(var_51, var_39, adj_51, adj_39, adj_52);
    wp::adj_float(var_13, adj_13, adj_51);
    wp::adj_div(var_48, var_49, var_50, adj_48, adj_49, adj_50);
    wp::adj_float(var_w, adj_w, adj_49);
    wp::adj_add(var_47, var_46, adj_47, adj_46, adj_48);
    wp::adj_float(var_24, adj_24, adj_47);
    // adj: s.uv = wp.vec2((float(i) + fu) / float(w), (float(j) + fv) / float(h))            <L 86>
    wp::adj_clamp(var_44, var_45, var_5, adj_44, adj_45, adj_5, adj_46);
    wp::adj_div(var_42, var_31, var_44, adj_42, adj_31, adj_44);
    wp::adj_sub(var_11, var_43, adj_11, adj_41, adj_42);
    wp::adj_address(var_cond, var_40, adj_cond, adj_40, adj_41);
    wp::adj_add(var_23, var_24, adj_23, adj_24, adj_40);
    // adj: fu = wp.clamp((u1 - cond[row + i]) / pc, 0.0, ONE_MINUS_EPS)                      <L 85>
    wp::adj_clamp(var_37, var_38, var_5, adj_37, adj_38, adj_5, adj_39);
    wp::adj_div(var_35, var_18, var_37, adj_35, adj_18, adj_37);
    wp::adj_sub(var_6, var_36, adj_6, adj_34, adj_35);
    wp::adj_address(var_marg, var_13, adj_marg, adj_13, adj_34);
    // adj: fv = wp.clamp((u0 - marg[j]) / pm, 0.0, ONE_MINUS_EPS)                            <L 84>
    wp::adj_sub(var_32, var_33, adj_28, adj_30, adj_31);
    wp::adj_address(var_cond, var_29, adj_cond, adj_29, adj_30);
    wp::adj_add(var_23, var_24, adj_23, adj_24, adj_29);
    wp::adj_address(var_cond, var_27, adj_cond, adj_27, adj_28);
    wp::adj_add(var_25, var_26, adj_25, adj_26, adj_27);
    wp::adj_add(var_23, var_24, adj_23, adj_24, adj_25);
    // adj: pc = cond[row + i + 1] - cond[row + i]                                            <L 83>
    adj_cdf_interval_0(var_cond, var_23, var_w, var_11, adj_cond, adj_23, adj_w, adj_11, adj_24);
    // adj: i = cdf_interval(cond, row, w, u1)                                                <L 82>
    wp::adj_mul(var_13, var_22, adj_13, adj_22, adj_23);
    wp::adj_add(var_w, var_21, adj_w, adj_21, adj_22);
    // adj: row = j * (w + 1)                                                                 <L 81>
    wp::adj_sub(var_19, var_20, adj_16, adj_17, adj_18);
    wp::adj_address(var_marg, var_13, adj_marg, adj_13, adj_17);
    wp::adj_address(var_marg, var_15, adj_marg, adj_15, adj_16);
    wp::adj_add(var_13, var_14, adj_13, adj_14, adj_15);
    // adj: pm = marg[j + 1] - marg[j]                                                        <L 80>
    adj_cdf_interval_0(var_marg, var_12, var_h, var_6, adj_marg, adj_12, adj_h, adj_6, adj_13);
    // adj: j = cdf_interval(marg, 0, h, u0)                                                  <L 79>
    wp::adj_min(var_10, var_5, adj_10, adj_5, adj_11);
    wp::adj_max(var_8, var_9, adj_8, adj_9, adj_10);
    wp::adj_extract(var_u, var_7, adj_u, adj_7, adj_8);
    // adj: u1 = wp.min(wp.max(u[1], 0.0), ONE_MINUS_EPS)                                     <L 78>
    wp::adj_min(var_4, var_5, adj_4, adj_5, adj_6);
    wp::adj_max(var_2, var_3, adj_2, adj_3, adj_4);
    wp::adj_extract(var_u, var_1, adj_u, adj_1, adj_2);
    // adj: u0 = wp.min(wp.max(u[0], 0.0), ONE_MINUS_EPS)                                     <L 77>
    // adj: s = Dist2DSample()                                                                <L 76>
    // adj: def sample_piecewise_2d(                                                          <L 71>
    return;
}


// /work/main/simulator/kernels/distributions.py:92
static void adj_pdf_piecewise_2d_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<2, wp::float32> var_uv,
    wp::array_t<wp::float32> & adj_marg,
    wp::array_t<wp::float32> & adj_cond,
    wp::int32 & adj_w,
    wp::int32 & adj_h,
    wp::vec_t<2, wp::float32> & adj_uv,
    wp::float32 & adj_ret)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::int32 var_4;
    const wp::int32 var_5 = 0;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    wp::int32 var_8;
    const wp::int32 var_9 = 1;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::int32 var_13;
    const wp::int32 var_14 = 0;
    const wp::int32 var_15 = 1;
    wp::int32 var_16;
    wp::int32 var_17;
    const wp::int32 var_18 = 1;
    wp::int32 var_19;
    wp::int32 var_20;
    wp::float32 var_21;
    const wp::int32 var_22 = 1;
    wp::int32 var_23;
    wp::float32* var_24;
    wp::float32* var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::int32 var_31;
    const wp::int32 var_32 = 1;
    wp::int32 var_33;
    wp::float32* var_34;
    wp::int32 var_35;
    wp::float32* var_36;
    wp::float32 var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::int32 adj_4 = {};
    wp::int32 adj_5 = {};
    wp::int32 adj_6 = {};
    wp::int32 adj_7 = {};
    wp::int32 adj_8 = {};
    wp::int32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::int32 adj_13 = {};
    wp::int32 adj_14 = {};
    wp::int32 adj_15 = {};
    wp::int32 adj_16 = {};
    wp::int32 adj_17 = {};
    wp::int32 adj_18 = {};
    wp::int32 adj_19 = {};
    wp::int32 adj_20 = {};
    wp::float32 adj_21 = {};
    wp::int32 adj_22 = {};
    wp::int32 adj_23 = {};
    wp::float32 adj_24 = {};
    wp::float32 adj_25 = {};
    wp::float32 adj_26 = {};
    wp::float32 adj_27 = {};
    wp::float32 adj_28 = {};
    wp::float32 adj_29 = {};
    wp::float32 adj_30 = {};
    wp::int32 adj_31 = {};
    wp::int32 adj_32 = {};
    wp::int32 adj_33 = {};
    wp::float32 adj_34 = {};
    wp::int32 adj_35 = {};
    wp::float32 adj_36 = {};
    wp::float32 adj_37 = {};
    wp::float32 adj_38 = {};
    wp::float32 adj_39 = {};
    wp::float32 adj_40 = {};
    wp::float32 adj_41 = {};
    //---------
    // forward
    // def pdf_piecewise_2d(                                                                  <L 93>
    // i = wp.clamp(int(uv[0] * float(w)), 0, w - 1)                                          <L 97>
    var_1 = wp::extract(var_uv, var_0);
    var_2 = wp::float(var_w);
    var_3 = wp::mul(var_1, var_2);
    var_4 = wp::int(var_3);
    var_7 = wp::sub(var_w, var_6);
    var_8 = wp::clamp(var_4, var_5, var_7);
    // j = wp.clamp(int(uv[1] * float(h)), 0, h - 1)                                          <L 98>
    var_10 = wp::extract(var_uv, var_9);
    var_11 = wp::float(var_h);
    var_12 = wp::mul(var_10, var_11);
    var_13 = wp::int(var_12);
    var_16 = wp::sub(var_h, var_15);
    var_17 = wp::clamp(var_13, var_14, var_16);
    // row = j * (w + 1)                                                                      <L 99>
    var_19 = wp::add(var_w, var_18);
    var_20 = wp::mul(var_17, var_19);
    // return (float(h) * (marg[j + 1] - marg[j])) * (float(w) * (cond[row + i + 1] - cond[row + i]))       <L 100>
    var_21 = wp::float(var_h);
    var_23 = wp::add(var_17, var_22);
    var_24 = wp::address(var_marg, var_23);
    var_25 = wp::address(var_marg, var_17);
    var_27 = wp::load(var_24);
    var_28 = wp::load(var_25);
    var_26 = wp::sub(var_27, var_28);
    var_29 = wp::mul(var_21, var_26);
    var_30 = wp::float(var_w);
    var_31 = wp::add(var_20, var_8);
    var_33 = wp::add(var_31, var_32);
    var_34 = wp::address(var_cond, var_33);
    var_35 = wp::add(var_20, var_8);
    var_36 = wp::address(var_cond, var_35);
    var_38 = wp::load(var_34);
    var_39 = wp::load(var_36);
    var_37 = wp::sub(var_38, var_39);
    var_40 = wp::mul(var_30, var_37);
    var_41 = wp::mul(var_29, var_40);
    goto label0;
    //---------
    // reverse
    label0:;
    adj_41 += adj_ret;
    wp::adj_mul(var_29, var_40, adj_29, adj_40, adj_41);
    wp::adj_mul(var_30, var_37, adj_30, adj_37, adj_40);
    wp::adj_sub(var_38, var_39, adj_34, adj_36, adj_37);
    wp::adj_address(var_cond, var_35, adj_cond, adj_35, adj_36);
    wp::adj_add(var_20, var_8, adj_20, adj_8, adj_35);
    wp::adj_address(var_cond, var_33, adj_cond, adj_33, adj_34);
    wp::adj_add(var_31, var_32, adj_31, adj_32, adj_33);
    wp::adj_add(var_20, var_8, adj_20, adj_8, adj_31);
    wp::adj_float(var_w, adj_w, adj_30);
    wp::adj_mul(var_21, var_26, adj_21, adj_26, adj_29);
    wp::adj_sub(var_27, var_28, adj_24, adj_25, adj_26);
    wp::adj_address(var_marg, var_17, adj_marg, adj_17, adj_25);
    wp::adj_address(var_marg, var_23, adj_marg, adj_23, adj_24);
    wp::adj_add(var_17, var_22, adj_17, adj_22, adj_23);
    wp::adj_float(var_h, adj_h, adj_21);
    // adj: return (float(h) * (marg[j + 1] - marg[j])) * (float(w) * (cond[row + i + 1] - cond[row + i]))  <L 100>
    wp::adj_mul(var_17, var_19, adj_17, adj_19, adj_20);
    wp::adj_add(var_w, var_18, adj_w, adj_18, adj_19);
    // adj: row = j * (w + 1)                                                                 <L 99>
    wp::adj_clamp(var_13, var_14, var_16, adj_13, adj_14, adj_16, adj_17);
    wp::adj_sub(var_h, var_15, adj_h, adj_15, adj_16);
    wp::adj_mul(var_10, var_11, adj_10, adj_11, adj_12);
    wp::adj_float(var_h, adj_h, adj_11);
    wp::adj_extract(var_uv, var_9, adj_uv, adj_9, adj_10);
    // adj: j = wp.clamp(int(uv[1] * float(h)), 0, h - 1)                                     <L 98>
    wp::adj_clamp(var_4, var_5, var_7, adj_4, adj_5, adj_7, adj_8);
    wp::adj_sub(var_w, var_6, adj_w, adj_6, adj_7);
    wp::adj_mul(var_1, var_2, adj_1, adj_2, adj_3);
    wp::adj_float(var_w, adj_w, adj_2);
    wp::adj_extract(var_uv, var_0, adj_uv, adj_0, adj_1);
    // adj: i = wp.clamp(int(uv[0] * float(w)), 0, w - 1)                                     <L 97>
    // adj: def pdf_piecewise_2d(                                                             <L 93>
    return;
}


// /work/main/simulator/kernels/distributions.py:116
static void adj_direction_to_latlong_uv_0(
    wp::vec_t<3, wp::float32> var_d,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez,
    wp::vec_t<3, wp::float32> & adj_d,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::vec_t<3, wp::float32> & adj_ez,
    wp::vec_t<2, wp::float32> & adj_ret)
{
    //---------
    // primal vars
    wp::float32 var_0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.5;
    const wp::float32 var_10 = 6.283185307179586;
    wp::float32 var_11;
    wp::float32 var_12;
    const wp::float32 var_13 = 3.141592653589793;
    wp::float32 var_14;
    wp::vec_t<2, wp::float32> var_15;
    //---------
    // dual vars
    wp::float32 adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::float32 adj_4 = {};
    wp::float32 adj_5 = {};
    wp::float32 adj_6 = {};
    wp::float32 adj_7 = {};
    wp::float32 adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::float32 adj_13 = {};
    wp::float32 adj_14 = {};
    wp::vec_t<2, wp::float32> adj_15 = {};
    //---------
    // forward
    // def direction_to_latlong_uv(d: wp.vec3, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec2:       <L 117>
    // lx = wp.dot(d, ex)                                                                     <L 120>
    var_0 = wp::dot(var_d, var_ex);
    // ly = wp.dot(d, ey)                                                                     <L 121>
    var_1 = wp::dot(var_d, var_ey);
    // lz = wp.dot(d, ez)                                                                     <L 122>
    var_2 = wp::dot(var_d, var_ez);
    // lon = wp.atan2(lx, lz)                                                                 <L 123>
    var_3 = wp::atan2(var_0, var_2);
    // theta = wp.atan2(wp.sqrt(lx * lx + lz * lz), ly)                                       <L 125>
    var_4 = wp::mul(var_0, var_0);
    var_5 = wp::mul(var_2, var_2);
    var_6 = wp::add(var_4, var_5);
    var_7 = wp::sqrt(var_6);
    var_8 = wp::atan2(var_7, var_1);
    // return wp.vec2(0.5 - lon / TWO_PI, theta / PI)                                         <L 126>
    var_11 = wp::div(var_3, var_10);
    var_12 = wp::sub(var_9, var_11);
    var_14 = wp::div(var_8, var_13);
    var_15 = wp::vec_t<2, wp::float32>(var_12, var_14);
    goto label0;
    //---------
    // reverse
    label0:;
    adj_15 += adj_ret;
    wp::adj_vec_t(var_12, var_14, adj_12, adj_14, adj_15);
    wp::adj_div(var_8, var_13, var_14, adj_8, adj_13, adj_14);
    wp::adj_sub(var_9, var_11, adj_9, adj_11, adj_12);
    wp::adj_div(var_3, var_10, var_11, adj_3, adj_10, adj_11);
    // adj: return wp.vec2(0.5 - lon / TWO_PI, theta / PI)                                    <L 126>
    wp::adj_atan2(var_7, var_1, adj_7, adj_1, adj_8);
    wp::adj_sqrt(var_6, var_7, adj_6, adj_7);
    wp::adj_add(var_4, var_5, adj_4, adj_5, adj_6);
    wp::adj_mul(var_2, var_2, adj_2, adj_2, adj_5);
    wp::adj_mul(var_0, var_0, adj_0, adj_0, adj_4);
    // adj: theta = wp.atan2(wp.sqrt(lx * lx + lz * lz), ly)                                  <L 125>
    wp::adj_atan2(var_0, var_2, adj_0, adj_2, adj_3);
    // adj: lon = wp.atan2(lx, lz)                                                            <L 123>
    wp::adj_dot(var_d, var_ez, adj_d, adj_ez, adj_2);
    // adj: lz = wp.dot(d, ez)                                                                <L 122>
    wp::adj_dot(var_d, var_ey, adj_d, adj_ey, adj_1);
    // adj: ly = wp.dot(d, ey)                                                                <L 121>
    wp::adj_dot(var_d, var_ex, adj_d, adj_ex, adj_0);
    // adj: lx = wp.dot(d, ex)                                                                <L 120>
    // adj: def direction_to_latlong_uv(d: wp.vec3, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec2:  <L 117>
    return;
}


// /work/main/simulator/kernels/distributions.py:161
static void adj_pdf_latlong_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez,
    wp::vec_t<3, wp::float32> var_d,
    wp::array_t<wp::float32> & adj_marg,
    wp::array_t<wp::float32> & adj_cond,
    wp::int32 & adj_w,
    wp::int32 & adj_h,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::vec_t<3, wp::float32> & adj_ez,
    wp::vec_t<3, wp::float32> & adj_d,
    wp::float32 & adj_ret)
{
    //---------
    // primal vars
    wp::float32 var_0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    const wp::float32 var_8 = 0.0;
    wp::vec_t<2, wp::float32> var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 19.739208802178716;
    wp::float32 var_12;
    wp::float32 var_13;
    //---------
    // dual vars
    wp::float32 adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::float32 adj_4 = {};
    wp::float32 adj_5 = {};
    wp::float32 adj_6 = {};
    bool adj_7 = {};
    wp::float32 adj_8 = {};
    wp::vec_t<2, wp::float32> adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::float32 adj_13 = {};
    //---------
    // forward
    // def pdf_latlong(                                                                       <L 162>
    // lx = wp.dot(d, ex)                                                                     <L 173>
    var_0 = wp::dot(var_d, var_ex);
    // lz = wp.dot(d, ez)                                                                     <L 174>
    var_1 = wp::dot(var_d, var_ez);
    // sin_t = wp.sqrt(lx * lx + lz * lz)                                                     <L 175>
    var_2 = wp::mul(var_0, var_0);
    var_3 = wp::mul(var_1, var_1);
    var_4 = wp::add(var_2, var_3);
    var_5 = wp::sqrt(var_4);
    // if sin_t <= 0.0:                                                                       <L 176>
    var_7 = (var_5 <= var_6);
    if (var_7) {
        // return 0.0                                                                         <L 177>
        goto label0;
    }
    // uv = direction_to_latlong_uv(d, ex, ey, ez)                                            <L 178>
    var_9 = direction_to_latlong_uv_0(var_d, var_ex, var_ey, var_ez);
    // return pdf_piecewise_2d(marg, cond, w, h, uv) / (TWO_PI_SQ * sin_t)                    <L 179>
    var_10 = pdf_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_9);
    var_12 = wp::mul(var_11, var_5);
    var_13 = wp::div(var_10, var_12);
    goto label1;
    //---------
    // reverse
    label1:;
    adj_13 += adj_ret;
    wp::adj_div(var_10, var_12, var_13, adj_10, adj_12, adj_13);
    wp::adj_mul(var_11, var_5, adj_11, adj_5, adj_12);
    adj_pdf_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_9, adj_marg, adj_cond, adj_w, adj_h, adj_9, adj_10);
    // adj: return pdf_piecewise_2d(marg, cond, w, h, uv) / (TWO_PI_SQ * sin_t)               <L 179>
    adj_direction_to_latlong_uv_0(var_d, var_ex, var_ey, var_ez, adj_d, adj_ex, adj_ey, adj_ez, adj_9);
    // adj: uv = direction_to_latlong_uv(d, ex, ey, ez)                                       <L 178>
    if (var_7) {
        label0:;
        adj_8 += adj_ret;
        // adj: return 0.0                                                                    <L 177>
    }
    // adj: if sin_t <= 0.0:                                                                  <L 176>
    wp::adj_sqrt(var_4, var_5, adj_4, adj_5);
    wp::adj_add(var_2, var_3, adj_2, adj_3, adj_4);
    wp::adj_mul(var_1, var_1, adj_1, adj_1, adj_3);
    wp::adj_mul(var_0, var_0, adj_0, adj_0, adj_2);
    // adj: sin_t = wp.sqrt(lx * lx + lz * lz)                                                <L 175>
    wp::adj_dot(var_d, var_ez, adj_d, adj_ez, adj_1);
    // adj: lz = wp.dot(d, ez)                                                                <L 174>
    wp::adj_dot(var_d, var_ex, adj_d, adj_ex, adj_0);
    // adj: lx = wp.dot(d, ex)                                                                <L 173>
    // adj: def pdf_latlong(                                                                  <L 162>
    return;
}


// /work/main/simulator/kernels/distributions.py:106
static void adj_latlong_uv_to_direction_0(
    wp::vec_t<2, wp::float32> var_uv,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez,
    wp::vec_t<2, wp::float32> & adj_uv,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::vec_t<3, wp::float32> & adj_ez,
    wp::vec_t<3, wp::float32> & adj_ret)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 3.141592653589793;
    const wp::float32 var_1 = 1.0;
    const wp::float32 var_2 = 2.0;
    const wp::int32 var_3 = 0;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    const wp::int32 var_8 = 1;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::float32 var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    //---------
    // dual vars
    wp::float32 adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::int32 adj_3 = {};
    wp::float32 adj_4 = {};
    wp::float32 adj_5 = {};
    wp::float32 adj_6 = {};
    wp::float32 adj_7 = {};
    wp::int32 adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::float32 adj_13 = {};
    wp::vec_t<3, wp::float32> adj_14 = {};
    wp::float32 adj_15 = {};
    wp::vec_t<3, wp::float32> adj_16 = {};
    wp::vec_t<3, wp::float32> adj_17 = {};
    wp::float32 adj_18 = {};
    wp::float32 adj_19 = {};
    wp::vec_t<3, wp::float32> adj_20 = {};
    wp::vec_t<3, wp::float32> adj_21 = {};
    //---------
    // forward
    // def latlong_uv_to_direction(uv: wp.vec2, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec3:       <L 107>
    // lon = PI * (1.0 - 2.0 * uv[0])                                                         <L 110>
    var_4 = wp::extract(var_uv, var_3);
    var_5 = wp::mul(var_2, var_4);
    var_6 = wp::sub(var_1, var_5);
    var_7 = wp::mul(var_0, var_6);
    // theta = PI * uv[1]                                                                     <L 111>
    var_9 = wp::extract(var_uv, var_8);
    var_10 = wp::mul(var_0, var_9);
    // st = wp.sin(theta)                                                                     <L 112>
    var_11 = wp::sin(var_10);
    // return (st * wp.sin(lon)) * ex + wp.cos(theta) * ey + (st * wp.cos(lon)) * ez          <L 113>
    var_12 = wp::sin(var_7);
    var_13 = wp::mul(var_11, var_12);
    var_14 = wp::mul(var_13, var_ex);
    var_15 = wp::cos(var_10);
    var_16 = wp::mul(var_15, var_ey);
    var_17 = wp::add(var_14, var_16);
    var_18 = wp::cos(var_7);
    var_19 = wp::mul(var_11, var_18);
    var_20 = wp::mul(var_19, var_ez);
    var_21 = wp::add(var_17, var_20);
    goto label0;
    //---------
    // reverse
    label0:;
    adj_21 += adj_ret;
    wp::adj_add(var_17, var_20, adj_17, adj_20, adj_21);
    wp::adj_mul(var_19, var_ez, adj_19, adj_ez, adj_20);
    wp::adj_mul(var_11, var_18, adj_11, adj_18, adj_19);
    wp::adj_cos(var_7, adj_7, adj_18);
    wp::adj_add(var_14, var_16, adj_14, adj_16, adj_17);
    wp::adj_mul(var_15, var_ey, adj_15, adj_ey, adj_16);
    wp::adj_cos(var_10, adj_10, adj_15);
    wp::adj_mul(var_13, var_ex, adj_13, adj_ex, adj_14);
    wp::adj_mul(var_11, var_12, adj_11, adj_12, adj_13);
    wp::adj_sin(var_7, adj_7, adj_12);
    // adj: return (st * wp.sin(lon)) * ex + wp.cos(theta) * ey + (st * wp.cos(lon)) * ez     <L 113>
    wp::adj_sin(var_10, adj_10, adj_11);
    // adj: st = wp.sin(theta)                                                                <L 112>
    wp::adj_mul(var_0, var_9, adj_0, adj_9, adj_10);
    wp::adj_extract(var_uv, var_8, adj_uv, adj_8, adj_9);
    // adj: theta = PI * uv[1]                                                                <L 111>
    wp::adj_mul(var_0, var_6, adj_0, adj_6, adj_7);
    wp::adj_sub(var_1, var_5, adj_1, adj_5, adj_6);
    wp::adj_mul(var_2, var_4, adj_2, adj_4, adj_5);
    wp::adj_extract(var_uv, var_3, adj_uv, adj_3, adj_4);
    // adj: lon = PI * (1.0 - 2.0 * uv[0])                                                    <L 110>
    // adj: def latlong_uv_to_direction(uv: wp.vec2, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec3:  <L 107>
    return;
}


// /work/main/simulator/kernels/distributions.py:137
static void adj_sample_latlong_0(
    wp::array_t<wp::float32> var_marg,
    wp::array_t<wp::float32> var_cond,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::vec_t<3, wp::float32> var_ez,
    wp::vec_t<2, wp::float32> var_u,
    wp::array_t<wp::float32> & adj_marg,
    wp::array_t<wp::float32> & adj_cond,
    wp::int32 & adj_w,
    wp::int32 & adj_h,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::vec_t<3, wp::float32> & adj_ez,
    wp::vec_t<2, wp::float32> & adj_u,
    LatLongSample_6aa5dbc2 & adj_ret)
{
    //---------
    // primal vars
    Dist2DSample_164324b3 var_0;
    LatLongSample_6aa5dbc2 var_1;
    wp::vec_t<2, wp::float32>* var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::int32* var_5;
    wp::int32 var_6;
    wp::int32 var_7;
    const wp::float32 var_8 = 3.141592653589793;
    wp::vec_t<2, wp::float32>* var_9;
    const wp::int32 var_10 = 1;
    wp::float32 var_11;
    wp::vec_t<2, wp::float32> var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    const wp::float32 var_15 = 0.0;
    const wp::float32 var_16 = 0.0;
    bool var_17;
    wp::float32* var_18;
    const wp::float32 var_19 = 19.739208802178716;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    //---------
    // dual vars
    Dist2DSample_164324b3 adj_0 = {};
    LatLongSample_6aa5dbc2 adj_1 = {};
    wp::vec_t<2, wp::float32> adj_2 = {};
    wp::vec_t<3, wp::float32> adj_3 = {};
    wp::vec_t<2, wp::float32> adj_4 = {};
    wp::int32 adj_5 = {};
    wp::int32 adj_6 = {};
    wp::int32 adj_7 = {};
    wp::float32 adj_8 = {};
    wp::vec_t<2, wp::float32> adj_9 = {};
    wp::int32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::vec_t<2, wp::float32> adj_12 = {};
    wp::float32 adj_13 = {};
    wp::float32 adj_14 = {};
    wp::float32 adj_15 = {};
    wp::float32 adj_16 = {};
    bool adj_17 = {};
    wp::float32 adj_18 = {};
    wp::float32 adj_19 = {};
    wp::float32 adj_20 = {};
    wp::float32 adj_21 = {};
    wp::float32 adj_22 = {};
    //---------
    // forward
    // def sample_latlong(                                                                    <L 138>
    // ds = sample_piecewise_2d(marg, cond, w, h, u)                                          <L 150>
    var_0 = sample_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_u);
    // s = LatLongSample()                                                                    <L 151>
    var_1 = LatLongSample_6aa5dbc2();
    // s.wi = latlong_uv_to_direction(ds.uv, ex, ey, ez)                                      <L 152>
    var_2 = &((var_0).uv);
    var_4 = wp::load(var_2);
    var_3 = latlong_uv_to_direction_0(var_4, var_ex, var_ey, var_ez);
    var_1.wi = var_3;
    // s.texel = ds.texel                                                                     <L 153>
    var_5 = &((var_0).texel);
    var_7 = wp::load(var_5);
    var_6 = wp::copy(var_7);
    var_1.texel = var_6;
    // sin_t = wp.sin(PI * ds.uv[1])                                                          <L 154>
    var_9 = &((var_0).uv);
    var_12 = wp::load(var_9);
    var_11 = wp::extract(var_12, var_10);
    var_13 = wp::mul(var_8, var_11);
    var_14 = wp::sin(var_13);
    // s.pdf = 0.0                                                                            <L 155>
    var_1.pdf = var_15;
    // if sin_t > 0.0:                                                                        <L 156>
    var_17 = (var_14 > var_16);
    if (var_17) {
        // s.pdf = ds.pdf / (TWO_PI_SQ * sin_t)                                               <L 157>
        var_18 = &((var_0).pdf);
        var_20 = wp::mul(var_19, var_14);
        var_22 = wp::load(var_18);
        var_21 = wp::div(var_22, var_20);
        var_1.pdf = var_21;
    }
    // return s                                                                               <L 158>
    goto label0;
    //---------
    // reverse
    label0:;
    adj_1 += adj_ret;
    // adj: return s                                                                          <L 158>
    if (var_17) {
        adj_21 += adj_1.pdf;
        adj_1.pdf = {};
        wp::adj_div(var_22, var_20, var_21, adj_18, adj_20, adj_21);
        wp::adj_mul(var_19, var_14, adj_19, adj_14, adj_20);
        adj_0.pdf += adj_18;
        // adj: s.pdf = ds.pdf / (TWO_PI_SQ * sin_t)                                          <L 157>
    }
    // adj: if sin_t > 0.0:                                                                   <L 156>
    adj_15 += adj_1.pdf;
    adj_1.pdf = {};
    // adj: s.pdf = 0.0                                                                       <L 155>
    wp::adj_sin(var_13, adj_13, adj_14);
    wp::adj_mul(var_8, var_11, adj_8, adj_11, adj_13);
    wp::adj_extract(var_12, var_10, adj_9, adj_10, adj_11);
    adj_0.uv += adj_9;
    // adj: sin_t = wp.sin(PI * ds.uv[1])                                                     <L 154>
    adj_1.texel = {};
    wp::adj_copy(var_7, adj_5, adj_6);
    adj_0.texel = adj_5;
    // adj: s.texel = ds.texel                                                                <L 153>
    adj_3 += adj_1.wi;
    adj_1.wi = {};
    adj_latlong_uv_to_direction_0(var_4, var_ex, var_ey, var_ez, adj_2, adj_ex, adj_ey, adj_ez, adj_3);
    adj_0.uv += adj_2;
    // adj: s.wi = latlong_uv_to_direction(ds.uv, ex, ey, ez)                                 <L 152>
    // adj: s = LatLongSample()                                                               <L 151>
    adj_sample_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_u, adj_marg, adj_cond, adj_w, adj_h, adj_u, adj_0);
    // adj: ds = sample_piecewise_2d(marg, cond, w, h, u)                                     <L 150>
    // adj: def sample_latlong(                                                               <L 138>
    return;
}

struct wp_args__draw_piecewise_2d_8231727f {
    wp::array_t<wp::float32> marg;
    wp::array_t<wp::float32> cond;
    wp::int32 w;
    wp::int32 h;
    wp::int32 seed;
    wp::array_t<wp::vec_t<2, wp::float32>> out_uv;
    wp::array_t<wp::float32> out_pdf;
    wp::array_t<wp::float32> out_pdf_twin;
    wp::array_t<wp::int32> out_texel;
};


template <bool wp_linear_contiguous>
static void _draw_piecewise_2d_8231727f_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__draw_piecewise_2d_8231727f *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__draw_piecewise_2d_8231727f wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_uv.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_pdf_twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_texel.strides[0] = sizeof(wp::int32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_marg = _wp_args->marg;
    wp::array_t<wp::float32> var_cond = _wp_args->cond;
    wp::int32 var_w = _wp_args->w;
    wp::int32 var_h = _wp_args->h;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<2, wp::float32>> var_out_uv = _wp_args->out_uv;
    wp::array_t<wp::float32> var_out_pdf = _wp_args->out_pdf;
    wp::array_t<wp::float32> var_out_pdf_twin = _wp_args->out_pdf_twin;
    wp::array_t<wp::int32> var_out_texel = _wp_args->out_texel;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    Dist2DSample_164324b3 var_5;
    wp::vec_t<2, wp::float32>* var_6;
    wp::vec_t<2, wp::float32> var_7;
    wp::vec_t<2, wp::float32> var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::vec_t<2, wp::float32>* var_12;
    wp::float32 var_13;
    wp::vec_t<2, wp::float32> var_14;
    wp::int32* var_15;
    wp::int32 var_16;
    wp::int32 var_17;
    //---------
    // forward
    // def _draw_piecewise_2d(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int, seed: int,       <L 108>
    // t = wp.tid()                                                                           <L 111>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, t)                                                            <L 112>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = D.sample_piecewise_2d(marg, cond, w, h, wp.vec2(wp.randf(rng), wp.randf(rng)))       <L 113>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_4);
    // out_uv[t] = s.uv                                                                       <L 114>
    var_6 = &((var_5).uv);
    var_8 = wp::load(var_6);
    var_7 = wp::copy(var_8);
    wp::array_store(var_out_uv, var_0, var_7);
    // out_pdf[t] = s.pdf                                                                     <L 115>
    var_9 = &((var_5).pdf);
    var_11 = wp::load(var_9);
    var_10 = wp::copy(var_11);
    wp::array_store(var_out_pdf, var_0, var_10);
    // out_pdf_twin[t] = D.pdf_piecewise_2d(marg, cond, w, h, s.uv)                           <L 116>
    var_12 = &((var_5).uv);
    var_14 = wp::load(var_12);
    var_13 = pdf_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_14);
    wp::array_store(var_out_pdf_twin, var_0, var_13);
    // out_texel[t] = s.texel                                                                 <L 117>
    var_15 = &((var_5).texel);
    var_17 = wp::load(var_15);
    var_16 = wp::copy(var_17);
    wp::array_store(var_out_texel, var_0, var_16);
}



template <bool wp_linear_contiguous>
static void _draw_piecewise_2d_8231727f_cpu_kernel_backward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__draw_piecewise_2d_8231727f *_wp_args,
    wp_args__draw_piecewise_2d_8231727f *_wp_adj_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__draw_piecewise_2d_8231727f wp_contiguous_args;
    wp_args__draw_piecewise_2d_8231727f wp_contiguous_adj_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_adj_args = *_wp_adj_args;
        wp_contiguous_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_uv.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_adj_args.out_uv.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_pdf_twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.out_pdf_twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_texel.strides[0] = sizeof(wp::int32);
        wp_contiguous_adj_args.out_texel.strides[0] = sizeof(wp::int32);
        _wp_args = &wp_contiguous_args;
        _wp_adj_args = &wp_contiguous_adj_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_marg = _wp_args->marg;
    wp::array_t<wp::float32> var_cond = _wp_args->cond;
    wp::int32 var_w = _wp_args->w;
    wp::int32 var_h = _wp_args->h;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<2, wp::float32>> var_out_uv = _wp_args->out_uv;
    wp::array_t<wp::float32> var_out_pdf = _wp_args->out_pdf;
    wp::array_t<wp::float32> var_out_pdf_twin = _wp_args->out_pdf_twin;
    wp::array_t<wp::int32> var_out_texel = _wp_args->out_texel;
    wp::array_t<wp::float32> adj_marg = _wp_adj_args->marg;
    wp::array_t<wp::float32> adj_cond = _wp_adj_args->cond;
    wp::int32 adj_w = _wp_adj_args->w;
    wp::int32 adj_h = _wp_adj_args->h;
    wp::int32 adj_seed = _wp_adj_args->seed;
    wp::array_t<wp::vec_t<2, wp::float32>> adj_out_uv = _wp_adj_args->out_uv;
    wp::array_t<wp::float32> adj_out_pdf = _wp_adj_args->out_pdf;
    wp::array_t<wp::float32> adj_out_pdf_twin = _wp_adj_args->out_pdf_twin;
    wp::array_t<wp::int32> adj_out_texel = _wp_adj_args->out_texel;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    Dist2DSample_164324b3 var_5;
    wp::vec_t<2, wp::float32>* var_6;
    wp::vec_t<2, wp::float32> var_7;
    wp::vec_t<2, wp::float32> var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::vec_t<2, wp::float32>* var_12;
    wp::float32 var_13;
    wp::vec_t<2, wp::float32> var_14;
    wp::int32* var_15;
    wp::int32 var_16;
    wp::int32 var_17;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::uint32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::vec_t<2, wp::float32> adj_4 = {};
    Dist2DSample_164324b3 adj_5 = {};
    wp::vec_t<2, wp::float32> adj_6 = {};
    wp::vec_t<2, wp::float32> adj_7 = {};
    wp::vec_t<2, wp::float32> adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::vec_t<2, wp::float32> adj_12 = {};
    wp::float32 adj_13 = {};
    wp::vec_t<2, wp::float32> adj_14 = {};
    wp::int32 adj_15 = {};
    wp::int32 adj_16 = {};
    wp::int32 adj_17 = {};
    //---------
    // forward
    // def _draw_piecewise_2d(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int, seed: int,       <L 108>
    // t = wp.tid()                                                                           <L 111>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, t)                                                            <L 112>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = D.sample_piecewise_2d(marg, cond, w, h, wp.vec2(wp.randf(rng), wp.randf(rng)))       <L 113>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_4);
    // out_uv[t] = s.uv                                                                       <L 114>
    var_6 = &((var_5).uv);
    var_8 = wp::load(var_6);
    var_7 = wp::copy(var_8);
    // wp::array_store(var_out_uv, var_0, var_7);
    // out_pdf[t] = s.pdf                                                                     <L 115>
    var_9 = &((var_5).pdf);
    var_11 = wp::load(var_9);
    var_10 = wp::copy(var_11);
    // wp::array_store(var_out_pdf, var_0, var_10);
    // out_pdf_twin[t] = D.pdf_piecewise_2d(marg, cond, w, h, s.uv)                           <L 116>
    var_12 = &((var_5).uv);
    var_14 = wp::load(var_12);
    var_13 = pdf_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_14);
    // wp::array_store(var_out_pdf_twin, var_0, var_13);
    // out_texel[t] = s.texel                                                                 <L 117>
    var_15 = &((var_5).texel);
    var_17 = wp::load(var_15);
    var_16 = wp::copy(var_17);
    // wp::array_store(var_out_texel, var_0, var_16);
    //---------
    // reverse
    wp::adj_array_store(var_out_texel, var_0, var_16, adj_out_texel, adj_0, adj_16);
    wp::adj_copy(var_17, adj_15, adj_16);
    adj_5.texel = adj_15;
    // adj: out_texel[t] = s.texel                                                            <L 117>
    wp::adj_array_store(var_out_pdf_twin, var_0, var_13, adj_out_pdf_twin, adj_0, adj_13);
    adj_pdf_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_14, adj_marg, adj_cond, adj_w, adj_h, adj_12, adj_13);
    adj_5.uv += adj_12;
    // adj: out_pdf_twin[t] = D.pdf_piecewise_2d(marg, cond, w, h, s.uv)                      <L 116>
    wp::adj_array_store(var_out_pdf, var_0, var_10, adj_out_pdf, adj_0, adj_10);
    wp::adj_copy(var_11, adj_9, adj_10);
    adj_5.pdf += adj_9;
    // adj: out_pdf[t] = s.pdf                                                                <L 115>
    wp::adj_array_store(var_out_uv, var_0, var_7, adj_out_uv, adj_0, adj_7);
    wp::adj_copy(var_8, adj_6, adj_7);
    adj_5.uv += adj_6;
    // adj: out_uv[t] = s.uv                                                                  <L 114>
    adj_sample_piecewise_2d_0(var_marg, var_cond, var_w, var_h, var_4, adj_marg, adj_cond, adj_w, adj_h, adj_4, adj_5);
    wp::adj_vec_t(var_2, var_3, adj_2, adj_3, adj_4);
    // adj: s = D.sample_piecewise_2d(marg, cond, w, h, wp.vec2(wp.randf(rng), wp.randf(rng)))  <L 113>
    // adj: rng = wp.rand_init(seed, t)                                                       <L 112>
    // adj: t = wp.tid()                                                                      <L 111>
    // adj: def _draw_piecewise_2d(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int, seed: int,  <L 108>
    return;
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _draw_piecewise_2d_8231727f_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_piecewise_2d_8231727f *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _draw_piecewise_2d_8231727f_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void _draw_piecewise_2d_8231727f_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_piecewise_2d_8231727f *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_uv.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_pdf_twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_texel.strides[0] == (int)sizeof(wp::int32)));
    if (wp_linear_contiguous)
        _draw_piecewise_2d_8231727f_cpu_forward_tasks<true>(dim, _wp_args);
    else
        _draw_piecewise_2d_8231727f_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void _draw_piecewise_2d_8231727f_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_piecewise_2d_8231727f *_wp_args)
{
    _draw_piecewise_2d_8231727f_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _draw_piecewise_2d_8231727f_cpu_backward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_piecewise_2d_8231727f *_wp_args,
    wp_args__draw_piecewise_2d_8231727f *_wp_adj_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _draw_piecewise_2d_8231727f_cpu_kernel_backward<wp_linear_contiguous>(
            *dim, task_index, _wp_args, _wp_adj_args);
    }
}

static WP_FORCEINLINE void _draw_piecewise_2d_8231727f_cpu_backward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_piecewise_2d_8231727f *_wp_args,
    wp_args__draw_piecewise_2d_8231727f *_wp_adj_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_uv.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_adj_args->out_uv.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_pdf_twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->out_pdf_twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_texel.strides[0] == (int)sizeof(wp::int32)) & (_wp_adj_args->out_texel.strides[0] == (int)sizeof(wp::int32)));
    if (wp_linear_contiguous)
        _draw_piecewise_2d_8231727f_cpu_backward_tasks<true>(dim, _wp_args, _wp_adj_args);
    else
        _draw_piecewise_2d_8231727f_cpu_backward_tasks<false>(dim, _wp_args, _wp_adj_args);
}

extern "C" {

WP_API void _draw_piecewise_2d_8231727f_cpu_backward(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_piecewise_2d_8231727f *_wp_args,
    wp_args__draw_piecewise_2d_8231727f *_wp_adj_args)
{
    _draw_piecewise_2d_8231727f_cpu_backward_dispatch(dim, _wp_args, _wp_adj_args);
}

} // extern C

struct wp_args__eval_latlong_83242c4f {
    wp::array_t<wp::float32> marg;
    wp::array_t<wp::float32> cond;
    wp::int32 w;
    wp::int32 h;
    wp::vec_t<3, wp::float32> ex;
    wp::vec_t<3, wp::float32> ey;
    wp::vec_t<3, wp::float32> ez;
    wp::array_t<wp::vec_t<3, wp::float32>> dirs;
    wp::array_t<wp::vec_t<2, wp::float32>> uvs;
    wp::array_t<wp::float32> out_pdf;
    wp::array_t<wp::vec_t<2, wp::float32>> out_uv;
    wp::array_t<wp::vec_t<3, wp::float32>> out_dir;
};


template <bool wp_linear_contiguous>
static void _eval_latlong_83242c4f_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__eval_latlong_83242c4f *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__eval_latlong_83242c4f wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.dirs.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.uvs.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_uv.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.out_dir.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_marg = _wp_args->marg;
    wp::array_t<wp::float32> var_cond = _wp_args->cond;
    wp::int32 var_w = _wp_args->w;
    wp::int32 var_h = _wp_args->h;
    wp::vec_t<3, wp::float32> var_ex = _wp_args->ex;
    wp::vec_t<3, wp::float32> var_ey = _wp_args->ey;
    wp::vec_t<3, wp::float32> var_ez = _wp_args->ez;
    wp::array_t<wp::vec_t<3, wp::float32>> var_dirs = _wp_args->dirs;
    wp::array_t<wp::vec_t<2, wp::float32>> var_uvs = _wp_args->uvs;
    wp::array_t<wp::float32> var_out_pdf = _wp_args->out_pdf;
    wp::array_t<wp::vec_t<2, wp::float32>> var_out_uv = _wp_args->out_uv;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out_dir = _wp_args->out_dir;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::float32 var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<3, wp::float32>* var_4;
    wp::vec_t<2, wp::float32> var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<2, wp::float32>* var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<2, wp::float32> var_9;
    //---------
    // forward
    // def _eval_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,       <L 134>
    // t = wp.tid()                                                                           <L 137>
    var_0 = builtin_tid1d();
    // out_pdf[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, dirs[t])                      <L 138>
    var_1 = wp::address(var_dirs, var_0);
    var_3 = wp::load(var_1);
    var_2 = pdf_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_3);
    wp::array_store(var_out_pdf, var_0, var_2);
    // out_uv[t] = D.direction_to_latlong_uv(dirs[t], ex, ey, ez)                             <L 139>
    var_4 = wp::address(var_dirs, var_0);
    var_6 = wp::load(var_4);
    var_5 = direction_to_latlong_uv_0(var_6, var_ex, var_ey, var_ez);
    wp::array_store(var_out_uv, var_0, var_5);
    // out_dir[t] = D.latlong_uv_to_direction(uvs[t], ex, ey, ez)                             <L 140>
    var_7 = wp::address(var_uvs, var_0);
    var_9 = wp::load(var_7);
    var_8 = latlong_uv_to_direction_0(var_9, var_ex, var_ey, var_ez);
    wp::array_store(var_out_dir, var_0, var_8);
}



template <bool wp_linear_contiguous>
static void _eval_latlong_83242c4f_cpu_kernel_backward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__eval_latlong_83242c4f *_wp_args,
    wp_args__eval_latlong_83242c4f *_wp_adj_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__eval_latlong_83242c4f wp_contiguous_args;
    wp_args__eval_latlong_83242c4f wp_contiguous_adj_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_adj_args = *_wp_adj_args;
        wp_contiguous_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.dirs.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_adj_args.dirs.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.uvs.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_adj_args.uvs.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_uv.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_adj_args.out_uv.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.out_dir.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_adj_args.out_dir.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        _wp_args = &wp_contiguous_args;
        _wp_adj_args = &wp_contiguous_adj_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_marg = _wp_args->marg;
    wp::array_t<wp::float32> var_cond = _wp_args->cond;
    wp::int32 var_w = _wp_args->w;
    wp::int32 var_h = _wp_args->h;
    wp::vec_t<3, wp::float32> var_ex = _wp_args->ex;
    wp::vec_t<3, wp::float32> var_ey = _wp_args->ey;
    wp::vec_t<3, wp::float32> var_ez = _wp_args->ez;
    wp::array_t<wp::vec_t<3, wp::float32>> var_dirs = _wp_args->dirs;
    wp::array_t<wp::vec_t<2, wp::float32>> var_uvs = _wp_args->uvs;
    wp::array_t<wp::float32> var_out_pdf = _wp_args->out_pdf;
    wp::array_t<wp::vec_t<2, wp::float32>> var_out_uv = _wp_args->out_uv;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out_dir = _wp_args->out_dir;
    wp::array_t<wp::float32> adj_marg = _wp_adj_args->marg;
    wp::array_t<wp::float32> adj_cond = _wp_adj_args->cond;
    wp::int32 adj_w = _wp_adj_args->w;
    wp::int32 adj_h = _wp_adj_args->h;
    wp::vec_t<3, wp::float32> adj_ex = _wp_adj_args->ex;
    wp::vec_t<3, wp::float32> adj_ey = _wp_adj_args->ey;
    wp::vec_t<3, wp::float32> adj_ez = _wp_adj_args->ez;
    wp::array_t<wp::vec_t<3, wp::float32>> adj_dirs = _wp_adj_args->dirs;
    wp::array_t<wp::vec_t<2, wp::float32>> adj_uvs = _wp_adj_args->uvs;
    wp::array_t<wp::float32> adj_out_pdf = _wp_adj_args->out_pdf;
    wp::array_t<wp::vec_t<2, wp::float32>> adj_out_uv = _wp_adj_args->out_uv;
    wp::array_t<wp::vec_t<3, wp::float32>> adj_out_dir = _wp_adj_args->out_dir;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::float32 var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<3, wp::float32>* var_4;
    wp::vec_t<2, wp::float32> var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<2, wp::float32>* var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<2, wp::float32> var_9;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::vec_t<3, wp::float32> adj_1 = {};
    wp::float32 adj_2 = {};
    wp::vec_t<3, wp::float32> adj_3 = {};
    wp::vec_t<3, wp::float32> adj_4 = {};
    wp::vec_t<2, wp::float32> adj_5 = {};
    wp::vec_t<3, wp::float32> adj_6 = {};
    wp::vec_t<2, wp::float32> adj_7 = {};
    wp::vec_t<3, wp::float32> adj_8 = {};
    wp::vec_t<2, wp::float32> adj_9 = {};
    //---------
    // forward
    // def _eval_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,       <L 134>
    // t = wp.tid()                                                                           <L 137>
    var_0 = builtin_tid1d();
    // out_pdf[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, dirs[t])                      <L 138>
    var_1 = wp::address(var_dirs, var_0);
    var_3 = wp::load(var_1);
    var_2 = pdf_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_3);
    // wp::array_store(var_out_pdf, var_0, var_2);
    // out_uv[t] = D.direction_to_latlong_uv(dirs[t], ex, ey, ez)                             <L 139>
    var_4 = wp::address(var_dirs, var_0);
    var_6 = wp::load(var_4);
    var_5 = direction_to_latlong_uv_0(var_6, var_ex, var_ey, var_ez);
    // wp::array_store(var_out_uv, var_0, var_5);
    // out_dir[t] = D.latlong_uv_to_direction(uvs[t], ex, ey, ez)                             <L 140>
    var_7 = wp::address(var_uvs, var_0);
    var_9 = wp::load(var_7);
    var_8 = latlong_uv_to_direction_0(var_9, var_ex, var_ey, var_ez);
    // wp::array_store(var_out_dir, var_0, var_8);
    //---------
    // reverse
    wp::adj_array_store(var_out_dir, var_0, var_8, adj_out_dir, adj_0, adj_8);
    adj_latlong_uv_to_direction_0(var_9, var_ex, var_ey, var_ez, adj_7, adj_ex, adj_ey, adj_ez, adj_8);
    wp::adj_address(var_uvs, var_0, adj_uvs, adj_0, adj_7);
    // adj: out_dir[t] = D.latlong_uv_to_direction(uvs[t], ex, ey, ez)                        <L 140>
    wp::adj_array_store(var_out_uv, var_0, var_5, adj_out_uv, adj_0, adj_5);
    adj_direction_to_latlong_uv_0(var_6, var_ex, var_ey, var_ez, adj_4, adj_ex, adj_ey, adj_ez, adj_5);
    wp::adj_address(var_dirs, var_0, adj_dirs, adj_0, adj_4);
    // adj: out_uv[t] = D.direction_to_latlong_uv(dirs[t], ex, ey, ez)                        <L 139>
    wp::adj_array_store(var_out_pdf, var_0, var_2, adj_out_pdf, adj_0, adj_2);
    adj_pdf_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_3, adj_marg, adj_cond, adj_w, adj_h, adj_ex, adj_ey, adj_ez, adj_1, adj_2);
    wp::adj_address(var_dirs, var_0, adj_dirs, adj_0, adj_1);
    // adj: out_pdf[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, dirs[t])                 <L 138>
    // adj: t = wp.tid()                                                                      <L 137>
    // adj: def _eval_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,  <L 134>
    return;
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _eval_latlong_83242c4f_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__eval_latlong_83242c4f *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _eval_latlong_83242c4f_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void _eval_latlong_83242c4f_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__eval_latlong_83242c4f *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->dirs.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->uvs.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_uv.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->out_dir.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)));
    if (wp_linear_contiguous)
        _eval_latlong_83242c4f_cpu_forward_tasks<true>(dim, _wp_args);
    else
        _eval_latlong_83242c4f_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void _eval_latlong_83242c4f_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args__eval_latlong_83242c4f *_wp_args)
{
    _eval_latlong_83242c4f_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _eval_latlong_83242c4f_cpu_backward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__eval_latlong_83242c4f *_wp_args,
    wp_args__eval_latlong_83242c4f *_wp_adj_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _eval_latlong_83242c4f_cpu_kernel_backward<wp_linear_contiguous>(
            *dim, task_index, _wp_args, _wp_adj_args);
    }
}

static WP_FORCEINLINE void _eval_latlong_83242c4f_cpu_backward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__eval_latlong_83242c4f *_wp_args,
    wp_args__eval_latlong_83242c4f *_wp_adj_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->dirs.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_adj_args->dirs.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->uvs.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_adj_args->uvs.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_uv.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_adj_args->out_uv.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->out_dir.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_adj_args->out_dir.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)));
    if (wp_linear_contiguous)
        _eval_latlong_83242c4f_cpu_backward_tasks<true>(dim, _wp_args, _wp_adj_args);
    else
        _eval_latlong_83242c4f_cpu_backward_tasks<false>(dim, _wp_args, _wp_adj_args);
}

extern "C" {

WP_API void _eval_latlong_83242c4f_cpu_backward(
    wp::launch_bounds_t<1> *dim,
    wp_args__eval_latlong_83242c4f *_wp_args,
    wp_args__eval_latlong_83242c4f *_wp_adj_args)
{
    _eval_latlong_83242c4f_cpu_backward_dispatch(dim, _wp_args, _wp_adj_args);
}

} // extern C

struct wp_args__draw_latlong_d8713875 {
    wp::array_t<wp::float32> marg;
    wp::array_t<wp::float32> cond;
    wp::int32 w;
    wp::int32 h;
    wp::vec_t<3, wp::float32> ex;
    wp::vec_t<3, wp::float32> ey;
    wp::vec_t<3, wp::float32> ez;
    wp::int32 seed;
    wp::array_t<wp::vec_t<3, wp::float32>> out_dir;
    wp::array_t<wp::float32> out_pdf;
    wp::array_t<wp::float32> out_pdf_twin;
};


template <bool wp_linear_contiguous>
static void _draw_latlong_d8713875_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__draw_latlong_d8713875 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__draw_latlong_d8713875 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_dir.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_pdf_twin.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_marg = _wp_args->marg;
    wp::array_t<wp::float32> var_cond = _wp_args->cond;
    wp::int32 var_w = _wp_args->w;
    wp::int32 var_h = _wp_args->h;
    wp::vec_t<3, wp::float32> var_ex = _wp_args->ex;
    wp::vec_t<3, wp::float32> var_ey = _wp_args->ey;
    wp::vec_t<3, wp::float32> var_ez = _wp_args->ez;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out_dir = _wp_args->out_dir;
    wp::array_t<wp::float32> var_out_pdf = _wp_args->out_pdf;
    wp::array_t<wp::float32> var_out_pdf_twin = _wp_args->out_pdf_twin;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    LatLongSample_6aa5dbc2 var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    //---------
    // forward
    // def _draw_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,       <L 121>
    // t = wp.tid()                                                                           <L 125>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, t)                                                            <L 126>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = D.sample_latlong(marg, cond, w, h, ex, ey, ez, wp.vec2(wp.randf(rng), wp.randf(rng)))       <L 127>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_4);
    // out_dir[t] = s.wi                                                                      <L 128>
    var_6 = &((var_5).wi);
    var_8 = wp::load(var_6);
    var_7 = wp::copy(var_8);
    wp::array_store(var_out_dir, var_0, var_7);
    // out_pdf[t] = s.pdf                                                                     <L 129>
    var_9 = &((var_5).pdf);
    var_11 = wp::load(var_9);
    var_10 = wp::copy(var_11);
    wp::array_store(var_out_pdf, var_0, var_10);
    // out_pdf_twin[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, s.wi)                    <L 130>
    var_12 = &((var_5).wi);
    var_14 = wp::load(var_12);
    var_13 = pdf_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_14);
    wp::array_store(var_out_pdf_twin, var_0, var_13);
}



template <bool wp_linear_contiguous>
static void _draw_latlong_d8713875_cpu_kernel_backward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__draw_latlong_d8713875 *_wp_args,
    wp_args__draw_latlong_d8713875 *_wp_adj_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__draw_latlong_d8713875 wp_contiguous_args;
    wp_args__draw_latlong_d8713875 wp_contiguous_adj_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_adj_args = *_wp_adj_args;
        wp_contiguous_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.marg.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.cond.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_dir.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_adj_args.out_dir.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.out_pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out_pdf_twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.out_pdf_twin.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
        _wp_adj_args = &wp_contiguous_adj_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_marg = _wp_args->marg;
    wp::array_t<wp::float32> var_cond = _wp_args->cond;
    wp::int32 var_w = _wp_args->w;
    wp::int32 var_h = _wp_args->h;
    wp::vec_t<3, wp::float32> var_ex = _wp_args->ex;
    wp::vec_t<3, wp::float32> var_ey = _wp_args->ey;
    wp::vec_t<3, wp::float32> var_ez = _wp_args->ez;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out_dir = _wp_args->out_dir;
    wp::array_t<wp::float32> var_out_pdf = _wp_args->out_pdf;
    wp::array_t<wp::float32> var_out_pdf_twin = _wp_args->out_pdf_twin;
    wp::array_t<wp::float32> adj_marg = _wp_adj_args->marg;
    wp::array_t<wp::float32> adj_cond = _wp_adj_args->cond;
    wp::int32 adj_w = _wp_adj_args->w;
    wp::int32 adj_h = _wp_adj_args->h;
    wp::vec_t<3, wp::float32> adj_ex = _wp_adj_args->ex;
    wp::vec_t<3, wp::float32> adj_ey = _wp_adj_args->ey;
    wp::vec_t<3, wp::float32> adj_ez = _wp_adj_args->ez;
    wp::int32 adj_seed = _wp_adj_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> adj_out_dir = _wp_adj_args->out_dir;
    wp::array_t<wp::float32> adj_out_pdf = _wp_adj_args->out_pdf;
    wp::array_t<wp::float32> adj_out_pdf_twin = _wp_adj_args->out_pdf_twin;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    LatLongSample_6aa5dbc2 var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::uint32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::vec_t<2, wp::float32> adj_4 = {};
    LatLongSample_6aa5dbc2 adj_5 = {};
    wp::vec_t<3, wp::float32> adj_6 = {};
    wp::vec_t<3, wp::float32> adj_7 = {};
    wp::vec_t<3, wp::float32> adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::vec_t<3, wp::float32> adj_12 = {};
    wp::float32 adj_13 = {};
    wp::vec_t<3, wp::float32> adj_14 = {};
    //---------
    // forward
    // def _draw_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,       <L 121>
    // t = wp.tid()                                                                           <L 125>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, t)                                                            <L 126>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = D.sample_latlong(marg, cond, w, h, ex, ey, ez, wp.vec2(wp.randf(rng), wp.randf(rng)))       <L 127>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_4);
    // out_dir[t] = s.wi                                                                      <L 128>
    var_6 = &((var_5).wi);
    var_8 = wp::load(var_6);
    var_7 = wp::copy(var_8);
    // wp::array_store(var_out_dir, var_0, var_7);
    // out_pdf[t] = s.pdf                                                                     <L 129>
    var_9 = &((var_5).pdf);
    var_11 = wp::load(var_9);
    var_10 = wp::copy(var_11);
    // wp::array_store(var_out_pdf, var_0, var_10);
    // out_pdf_twin[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, s.wi)                    <L 130>
    var_12 = &((var_5).wi);
    var_14 = wp::load(var_12);
    var_13 = pdf_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_14);
    // wp::array_store(var_out_pdf_twin, var_0, var_13);
    //---------
    // reverse
    wp::adj_array_store(var_out_pdf_twin, var_0, var_13, adj_out_pdf_twin, adj_0, adj_13);
    adj_pdf_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_14, adj_marg, adj_cond, adj_w, adj_h, adj_ex, adj_ey, adj_ez, adj_12, adj_13);
    adj_5.wi += adj_12;
    // adj: out_pdf_twin[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, s.wi)               <L 130>
    wp::adj_array_store(var_out_pdf, var_0, var_10, adj_out_pdf, adj_0, adj_10);
    wp::adj_copy(var_11, adj_9, adj_10);
    adj_5.pdf += adj_9;
    // adj: out_pdf[t] = s.pdf                                                                <L 129>
    wp::adj_array_store(var_out_dir, var_0, var_7, adj_out_dir, adj_0, adj_7);
    wp::adj_copy(var_8, adj_6, adj_7);
    adj_5.wi += adj_6;
    // adj: out_dir[t] = s.wi                                                                 <L 128>
    adj_sample_latlong_0(var_marg, var_cond, var_w, var_h, var_ex, var_ey, var_ez, var_4, adj_marg, adj_cond, adj_w, adj_h, adj_ex, adj_ey, adj_ez, adj_4, adj_5);
    wp::adj_vec_t(var_2, var_3, adj_2, adj_3, adj_4);
    // adj: s = D.sample_latlong(marg, cond, w, h, ex, ey, ez, wp.vec2(wp.randf(rng), wp.randf(rng)))  <L 127>
    // adj: rng = wp.rand_init(seed, t)                                                       <L 126>
    // adj: t = wp.tid()                                                                      <L 125>
    // adj: def _draw_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,  <L 121>
    return;
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _draw_latlong_d8713875_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_latlong_d8713875 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _draw_latlong_d8713875_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void _draw_latlong_d8713875_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_latlong_d8713875 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_dir.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_pdf_twin.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        _draw_latlong_d8713875_cpu_forward_tasks<true>(dim, _wp_args);
    else
        _draw_latlong_d8713875_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void _draw_latlong_d8713875_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_latlong_d8713875 *_wp_args)
{
    _draw_latlong_d8713875_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _draw_latlong_d8713875_cpu_backward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_latlong_d8713875 *_wp_args,
    wp_args__draw_latlong_d8713875 *_wp_adj_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _draw_latlong_d8713875_cpu_kernel_backward<wp_linear_contiguous>(
            *dim, task_index, _wp_args, _wp_adj_args);
    }
}

static WP_FORCEINLINE void _draw_latlong_d8713875_cpu_backward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_latlong_d8713875 *_wp_args,
    wp_args__draw_latlong_d8713875 *_wp_adj_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->marg.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->cond.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_dir.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_adj_args->out_dir.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->out_pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out_pdf_twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->out_pdf_twin.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        _draw_latlong_d8713875_cpu_backward_tasks<true>(dim, _wp_args, _wp_adj_args);
    else
        _draw_latlong_d8713875_cpu_backward_tasks<false>(dim, _wp_args, _wp_adj_args);
}

extern "C" {

WP_API void _draw_latlong_d8713875_cpu_backward(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_latlong_d8713875 *_wp_args,
    wp_args__draw_latlong_d8713875 *_wp_adj_args)
{
    _draw_latlong_d8713875_cpu_backward_dispatch(dim, _wp_args, _wp_adj_args);
}

} // extern C

