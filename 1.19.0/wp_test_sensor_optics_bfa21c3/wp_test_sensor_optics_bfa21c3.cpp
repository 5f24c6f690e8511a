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


struct OpticsSample_915df1ad
{
    wp::vec_t<3, wp::float32> local;
    wp::float32 pdf;
    wp::float32 weight;


    OpticsSample_915df1ad() = default;
    CUDA_CALLABLE OpticsSample_915df1ad(wp::vec_t<3, wp::float32> const& local,
    wp::float32 const& pdf = {},
    wp::float32 const& weight = {})
        : local{local}
        , pdf{pdf}
        , weight{weight}

    {
    }

    CUDA_CALLABLE OpticsSample_915df1ad& operator += (const OpticsSample_915df1ad& rhs)
    {    local += rhs.local;
    pdf += rhs.pdf;
    weight += rhs.weight;

        return *this;}

};

static CUDA_CALLABLE void adj_OpticsSample_915df1ad(wp::vec_t<3, wp::float32> const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::vec_t<3, wp::float32> & adj_local,
    wp::float32 & adj_pdf,
    wp::float32 & adj_weight,
    OpticsSample_915df1ad & adj_ret)
{
    adj_local += adj_ret.local;
    adj_pdf += adj_ret.pdf;
    adj_weight += adj_ret.weight;
}

// Required when compiling adjoints.
CUDA_CALLABLE OpticsSample_915df1ad add(const OpticsSample_915df1ad& a, const OpticsSample_915df1ad& b)
{
    return OpticsSample_915df1ad();
}

CUDA_CALLABLE void adj_atomic_add(OpticsSample_915df1ad* p, OpticsSample_915df1ad t)
{
    wp::adj_atomic_add(&p->local, t.local);
    wp::adj_atomic_add(&p->pdf, t.pdf);
    wp::adj_atomic_add(&p->weight, t.weight);
}




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




struct OpticsRec_3192f450
{
    wp::int32 kind;
    wp::float32 exponent;
    wp::float32 integral;
    wp::int32 n_theta;
    wp::int32 n_phi;
    wp::array_t<wp::float32> theta;
    wp::array_t<wp::float32> phi;
    wp::array_t<wp::float32> values;
    wp::int32 rows;
    wp::int32 cols;
    wp::float32 d_theta;
    wp::array_t<wp::float32> marg;
    wp::array_t<wp::float32> cond;
    wp::array_t<wp::float32> row_mu;
    wp::array_t<wp::float32> row_dmu;


    OpticsRec_3192f450() = default;
    CUDA_CALLABLE OpticsRec_3192f450(wp::int32 const& kind,
    wp::float32 const& exponent = {},
    wp::float32 const& integral = {},
    wp::int32 const& n_theta = {},
    wp::int32 const& n_phi = {},
    wp::array_t<wp::float32> const& theta = {},
    wp::array_t<wp::float32> const& phi = {},
    wp::array_t<wp::float32> const& values = {},
    wp::int32 const& rows = {},
    wp::int32 const& cols = {},
    wp::float32 const& d_theta = {},
    wp::array_t<wp::float32> const& marg = {},
    wp::array_t<wp::float32> const& cond = {},
    wp::array_t<wp::float32> const& row_mu = {},
    wp::array_t<wp::float32> const& row_dmu = {})
        : kind{kind}
        , exponent{exponent}
        , integral{integral}
        , n_theta{n_theta}
        , n_phi{n_phi}
        , theta{theta}
        , phi{phi}
        , values{values}
        , rows{rows}
        , cols{cols}
        , d_theta{d_theta}
        , marg{marg}
        , cond{cond}
        , row_mu{row_mu}
        , row_dmu{row_dmu}

    {
    }

    CUDA_CALLABLE OpticsRec_3192f450& operator += (const OpticsRec_3192f450& rhs)
    {    kind += rhs.kind;
    exponent += rhs.exponent;
    integral += rhs.integral;
    n_theta += rhs.n_theta;
    n_phi += rhs.n_phi;
    rows += rhs.rows;
    cols += rhs.cols;
    d_theta += rhs.d_theta;

        return *this;}

};

static CUDA_CALLABLE void adj_OpticsRec_3192f450(wp::int32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::int32 & adj_kind,
    wp::float32 & adj_exponent,
    wp::float32 & adj_integral,
    wp::int32 & adj_n_theta,
    wp::int32 & adj_n_phi,
    wp::array_t<wp::float32> & adj_theta,
    wp::array_t<wp::float32> & adj_phi,
    wp::array_t<wp::float32> & adj_values,
    wp::int32 & adj_rows,
    wp::int32 & adj_cols,
    wp::float32 & adj_d_theta,
    wp::array_t<wp::float32> & adj_marg,
    wp::array_t<wp::float32> & adj_cond,
    wp::array_t<wp::float32> & adj_row_mu,
    wp::array_t<wp::float32> & adj_row_dmu,
    OpticsRec_3192f450 & adj_ret)
{
    adj_kind += adj_ret.kind;
    adj_exponent += adj_ret.exponent;
    adj_integral += adj_ret.integral;
    adj_n_theta += adj_ret.n_theta;
    adj_n_phi += adj_ret.n_phi;
    adj_theta = adj_ret.theta;
    adj_phi = adj_ret.phi;
    adj_values = adj_ret.values;
    adj_rows += adj_ret.rows;
    adj_cols += adj_ret.cols;
    adj_d_theta += adj_ret.d_theta;
    adj_marg = adj_ret.marg;
    adj_cond = adj_ret.cond;
    adj_row_mu = adj_ret.row_mu;
    adj_row_dmu = adj_ret.row_dmu;
}

// Required when compiling adjoints.
CUDA_CALLABLE OpticsRec_3192f450 add(const OpticsRec_3192f450& a, const OpticsRec_3192f450& b)
{
    return OpticsRec_3192f450();
}

CUDA_CALLABLE void adj_atomic_add(OpticsRec_3192f450* p, OpticsRec_3192f450 t)
{
    wp::adj_atomic_add(&p->kind, t.kind);
    wp::adj_atomic_add(&p->exponent, t.exponent);
    wp::adj_atomic_add(&p->integral, t.integral);
    wp::adj_atomic_add(&p->n_theta, t.n_theta);
    wp::adj_atomic_add(&p->n_phi, t.n_phi);
    wp::adj_atomic_add(&p->theta, t.theta);
    wp::adj_atomic_add(&p->phi, t.phi);
    wp::adj_atomic_add(&p->values, t.values);
    wp::adj_atomic_add(&p->rows, t.rows);
    wp::adj_atomic_add(&p->cols, t.cols);
    wp::adj_atomic_add(&p->d_theta, t.d_theta);
    wp::adj_atomic_add(&p->marg, t.marg);
    wp::adj_atomic_add(&p->cond, t.cond);
    wp::adj_atomic_add(&p->row_mu, t.row_mu);
    wp::adj_atomic_add(&p->row_dmu, t.row_dmu);
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


// /work/main/simulator/kernels/optics.py:183
static wp::float32 pdf_optics_0(
    OpticsRec_3192f450 var_o,
    wp::vec_t<3, wp::float32> var_local)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    const wp::float32 var_4 = 0.0;
    wp::int32* var_5;
    const wp::int32 var_6 = 1;
    bool var_7;
    wp::int32 var_8;
    wp::float32* var_9;
    const wp::float32 var_10 = 1.0;
    wp::float32 var_11;
    wp::float32 var_12;
    const wp::float32 var_13 = 6.283185307179586;
    wp::float32 var_14;
    const wp::float32 var_15 = 1.0;
    wp::float32 var_16;
    wp::float32* var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    const wp::int32 var_21 = 0;
    wp::float32 var_22;
    const wp::int32 var_23 = 0;
    wp::float32 var_24;
    wp::float32 var_25;
    const wp::int32 var_26 = 1;
    wp::float32 var_27;
    const wp::int32 var_28 = 1;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32 var_33;
    wp::float32* var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::int32 var_37;
    wp::int32* var_38;
    bool var_39;
    wp::int32 var_40;
    const wp::float32 var_41 = 0.0;
    wp::array_t<wp::float32>* var_42;
    wp::float32* var_43;
    wp::array_t<wp::float32> var_44;
    wp::float32 var_45;
    wp::float32 var_46;
    wp::array_t<wp::float32>* var_47;
    wp::float32* var_48;
    wp::array_t<wp::float32> var_49;
    wp::float32 var_50;
    wp::float32 var_51;
    const wp::float32 var_52 = 0.0;
    const wp::float32 var_53 = 0.99999994;
    wp::float32 var_54;
    const wp::int32 var_55 = 1;
    wp::float32 var_56;
    const wp::int32 var_57 = 0;
    wp::float32 var_58;
    wp::float32 var_59;
    const wp::float32 var_60 = 0.0;
    bool var_61;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    const wp::float32 var_65 = 0.0;
    const wp::float32 var_66 = 0.99999994;
    wp::float32 var_67;
    wp::float32 var_68;
    wp::float32 var_69;
    wp::int32* var_70;
    wp::float32 var_71;
    wp::int32 var_72;
    wp::float32 var_73;
    wp::vec_t<2, wp::float32> var_74;
    wp::array_t<wp::float32>* var_75;
    wp::array_t<wp::float32>* var_76;
    wp::int32* var_77;
    wp::int32* var_78;
    wp::float32 var_79;
    wp::array_t<wp::float32> var_80;
    wp::array_t<wp::float32> var_81;
    wp::int32 var_82;
    wp::int32 var_83;
    wp::int32* var_84;
    wp::float32 var_85;
    wp::int32 var_86;
    wp::array_t<wp::float32>* var_87;
    wp::float32* var_88;
    wp::array_t<wp::float32> var_89;
    wp::float32 var_90;
    wp::float32 var_91;
    wp::float32 var_92;
    wp::float32 var_93;
    //---------
    // forward
    // def pdf_optics(o: OpticsRec, local: wp.vec3) -> float:                                 <L 184>
    // z = local[2]                                                                           <L 186>
    var_1 = wp::extract(var_local, var_0);
    // if z <= 0.0:                                                                           <L 187>
    var_3 = (var_1 <= var_2);
    if (var_3) {
        // return 0.0                                                                         <L 188>
        return var_4;
    }
    // if o.kind == 1:                                                                        <L 189>
    var_5 = &((var_o).kind);
    var_8 = wp::load(var_5);
    var_7 = (var_8 == var_6);
    if (var_7) {
        // return (o.exponent + 1.0) / TWO_PI * wp.pow(wp.min(z, 1.0), o.exponent)            <L 190>
        var_9 = &((var_o).exponent);
        var_12 = wp::load(var_9);
        var_11 = wp::add(var_12, var_10);
        var_14 = wp::div(var_11, var_13);
        var_16 = wp::min(var_1, var_15);
        var_17 = &((var_o).exponent);
        var_19 = wp::load(var_17);
        var_18 = wp::pow(var_16, var_19);
        var_20 = wp::mul(var_14, var_18);
        return var_20;
    }
    // theta = wp.atan2(wp.sqrt(local[0] * local[0] + local[1] * local[1]), z)                <L 191>
    var_22 = wp::extract(var_local, var_21);
    var_24 = wp::extract(var_local, var_23);
    var_25 = wp::mul(var_22, var_24);
    var_27 = wp::extract(var_local, var_26);
    var_29 = wp::extract(var_local, var_28);
    var_30 = wp::mul(var_27, var_29);
    var_31 = wp::add(var_25, var_30);
    var_32 = wp::sqrt(var_31);
    var_33 = wp::atan2(var_32, var_1);
    // j = int(theta / o.d_theta)                                                             <L 192>
    var_34 = &((var_o).d_theta);
    var_36 = wp::load(var_34);
    var_35 = wp::div(var_33, var_36);
    var_37 = wp::int(var_35);
    // if j >= o.rows:                                                                        <L 193>
    var_38 = &((var_o).rows);
    var_40 = wp::load(var_38);
    var_39 = (var_37 >= var_40);
    if (var_39) {
        // return 0.0                                                                         <L 194>
        return var_41;
    }
    // fv = wp.clamp((o.row_mu[j] - z) / o.row_dmu[j], 0.0, 0.99999994)                       <L 195>
    var_42 = &((var_o).row_mu);
    var_44 = wp::load(var_42);
    var_43 = wp::address(var_44, var_37);
    var_46 = wp::load(var_43);
    var_45 = wp::sub(var_46, var_1);
    var_47 = &((var_o).row_dmu);
    var_49 = wp::load(var_47);
    var_48 = wp::address(var_49, var_37);
    var_51 = wp::load(var_48);
    var_50 = wp::div(var_45, var_51);
    var_54 = wp::clamp(var_50, var_52, var_53);
    // phi = wp.atan2(local[1], local[0])                                                     <L 196>
    var_56 = wp::extract(var_local, var_55);
    var_58 = wp::extract(var_local, var_57);
    var_59 = wp::atan2(var_56, var_58);
    // if phi < 0.0:                                                                          <L 197>
    var_61 = (var_59 < var_60);
    if (var_61) {
        // phi = phi + TWO_PI                                                                 <L 198>
        var_62 = wp::add(var_59, var_13);
    }
    var_63 = wp::where(var_61, var_62, var_59);
    // uv = wp.vec2(wp.clamp(phi / TWO_PI, 0.0, 0.99999994), (float(j) + fv) / float(o.rows))       <L 199>
    var_64 = wp::div(var_63, var_13);
    var_67 = wp::clamp(var_64, var_65, var_66);
    var_68 = wp::float(var_37);
    var_69 = wp::add(var_68, var_54);
    var_70 = &((var_o).rows);
    var_72 = wp::load(var_70);
    var_71 = wp::float(var_72);
    var_73 = wp::div(var_69, var_71);
    var_74 = wp::vec_t<2, wp::float32>(var_67, var_73);
    // return pdf_piecewise_2d(o.marg, o.cond, o.cols, o.rows, uv) / (float(o.rows) * o.row_dmu[j] * TWO_PI)       <L 200>
    var_75 = &((var_o).marg);
    var_76 = &((var_o).cond);
    var_77 = &((var_o).cols);
    var_78 = &((var_o).rows);
    var_80 = wp::load(var_75);
    var_81 = wp::load(var_76);
    var_82 = wp::load(var_77);
    var_83 = wp::load(var_78);
    var_79 = pdf_piecewise_2d_0(var_80, var_81, var_82, var_83, var_74);
    var_84 = &((var_o).rows);
    var_86 = wp::load(var_84);
    var_85 = wp::float(var_86);
    var_87 = &((var_o).row_dmu);
    var_89 = wp::load(var_87);
    var_88 = wp::address(var_89, var_37);
    var_91 = wp::load(var_88);
    var_90 = wp::mul(var_85, var_91);
    var_92 = wp::mul(var_90, var_13);
    var_93 = wp::div(var_79, var_92);
    return var_93;
}


// /work/main/simulator/kernels/optics.py:94
static wp::int32 knot_interval_0(
    wp::array_t<wp::float32> var_a,
    wp::int32 var_n,
    wp::float32 var_x)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::int32 var_1;
    const wp::int32 var_2 = 2;
    wp::int32 var_3;
    bool var_4;
    wp::int32 var_5;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    const wp::int32 var_8 = 2;
    wp::int32 var_9;
    wp::float32* var_10;
    bool var_11;
    wp::float32 var_12;
    wp::int32 var_13;
    const wp::int32 var_14 = 1;
    wp::int32 var_15;
    wp::int32 var_16;
    wp::int32 var_17;
    //---------
    // forward
    // def knot_interval(a: wp.array(dtype=float), n: int, x: float) -> int:                  <L 95>
    // lo = int(0)                                                                            <L 98>
    var_1 = wp::int(var_0);
    // hi = n - 2                                                                             <L 99>
    var_3 = wp::sub(var_n, var_2);
    // while lo < hi:                                                                         <L 100>
    start_while_0:;
    var_4 = (var_1 < var_3);
    if ((var_4) == false) goto end_while_0;
        // mid = (lo + hi + 1) // 2                                                           <L 101>
        var_5 = wp::add(var_1, var_3);
        var_7 = wp::add(var_5, var_6);
        var_9 = wp::floordiv(var_7, var_8);
        // if a[mid] <= x:                                                                    <L 102>
        var_10 = wp::address(var_a, var_9);
        var_12 = wp::load(var_10);
        var_11 = (var_12 <= var_x);
        if (var_11) {
            // lo = mid                                                                       <L 103>
            var_13 = wp::copy(var_9);
        }
        if (!var_11) {
            // hi = mid - 1                                                                   <L 105>
            var_15 = wp::sub(var_9, var_14);
        }
        var_16 = wp::where(var_11, var_13, var_1);
        var_17 = wp::where(var_11, var_3, var_15);
        wp::assign(var_1, var_16);
        wp::assign(var_3, var_17);
    goto start_while_0;
    end_while_0:;
    // return lo                                                                              <L 106>
    return var_1;
}


// /work/main/simulator/kernels/optics.py:109
static wp::float32 table_column_0(
    OpticsRec_3192f450 var_o,
    wp::int32 var_k,
    wp::float32 var_theta)
{
    //---------
    // primal vars
    wp::array_t<wp::float32>* var_0;
    wp::int32* var_1;
    const wp::int32 var_2 = 1;
    wp::int32 var_3;
    wp::int32 var_4;
    wp::float32* var_5;
    wp::array_t<wp::float32> var_6;
    bool var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.0;
    wp::array_t<wp::float32>* var_10;
    wp::int32* var_11;
    wp::int32 var_12;
    wp::array_t<wp::float32> var_13;
    wp::int32 var_14;
    wp::array_t<wp::float32>* var_15;
    wp::float32* var_16;
    wp::array_t<wp::float32> var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::array_t<wp::float32>* var_20;
    const wp::int32 var_21 = 1;
    wp::int32 var_22;
    wp::float32* var_23;
    wp::array_t<wp::float32> var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    const wp::float32 var_30 = 0.0;
    const wp::float32 var_31 = 1.0;
    wp::float32 var_32;
    wp::int32* var_33;
    wp::int32 var_34;
    wp::int32 var_35;
    wp::array_t<wp::float32>* var_36;
    wp::int32 var_37;
    wp::float32* var_38;
    wp::array_t<wp::float32> var_39;
    wp::array_t<wp::float32>* var_40;
    wp::int32 var_41;
    const wp::int32 var_42 = 1;
    wp::int32 var_43;
    wp::float32* var_44;
    wp::array_t<wp::float32> var_45;
    wp::array_t<wp::float32>* var_46;
    wp::int32 var_47;
    wp::float32* var_48;
    wp::array_t<wp::float32> var_49;
    wp::float32 var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::float32 var_55;
    //---------
    // forward
    // def table_column(o: OpticsRec, k: int, theta: float) -> float:                         <L 110>
    // if theta > o.theta[o.n_theta - 1]:                                                     <L 112>
    var_0 = &((var_o).theta);
    var_1 = &((var_o).n_theta);
    var_4 = wp::load(var_1);
    var_3 = wp::sub(var_4, var_2);
    var_6 = wp::load(var_0);
    var_5 = wp::address(var_6, var_3);
    var_8 = wp::load(var_5);
    var_7 = (var_theta > var_8);
    if (var_7) {
        // return 0.0                                                                         <L 113>
        return var_9;
    }
    // j = knot_interval(o.theta, o.n_theta, theta)                                           <L 114>
    var_10 = &((var_o).theta);
    var_11 = &((var_o).n_theta);
    var_13 = wp::load(var_10);
    var_14 = wp::load(var_11);
    var_12 = knot_interval_0(var_13, var_14, var_theta);
    // t0 = o.theta[j]                                                                        <L 115>
    var_15 = &((var_o).theta);
    var_17 = wp::load(var_15);
    var_16 = wp::address(var_17, var_12);
    var_19 = wp::load(var_16);
    var_18 = wp::copy(var_19);
    // t1 = o.theta[j + 1]                                                                    <L 116>
    var_20 = &((var_o).theta);
    var_22 = wp::add(var_12, var_21);
    var_24 = wp::load(var_20);
    var_23 = wp::address(var_24, var_22);
    var_26 = wp::load(var_23);
    var_25 = wp::copy(var_26);
    // f = wp.clamp((theta - t0) / (t1 - t0), 0.0, 1.0)                                       <L 117>
    var_27 = wp::sub(var_theta, var_18);
    var_28 = wp::sub(var_25, var_18);
    var_29 = wp::div(var_27, var_28);
    var_32 = wp::clamp(var_29, var_30, var_31);
    // base = k * o.n_theta                                                                   <L 118>
    var_33 = &((var_o).n_theta);
    var_35 = wp::load(var_33);
    var_34 = wp::mul(var_k, var_35);
    // return o.values[base + j] + f * (o.values[base + j + 1] - o.values[base + j])          <L 119>
    var_36 = &((var_o).values);
    var_37 = wp::add(var_34, var_12);
    var_39 = wp::load(var_36);
    var_38 = wp::address(var_39, var_37);
    var_40 = &((var_o).values);
    var_41 = wp::add(var_34, var_12);
    var_43 = wp::add(var_41, var_42);
    var_45 = wp::load(var_40);
    var_44 = wp::address(var_45, var_43);
    var_46 = &((var_o).values);
    var_47 = wp::add(var_34, var_12);
    var_49 = wp::load(var_46);
    var_48 = wp::address(var_49, var_47);
    var_51 = wp::load(var_44);
    var_52 = wp::load(var_48);
    var_50 = wp::sub(var_51, var_52);
    var_53 = wp::mul(var_32, var_50);
    var_55 = wp::load(var_38);
    var_54 = wp::add(var_55, var_53);
    return var_54;
}


// /work/main/simulator/kernels/optics.py:122
static wp::float32 optics_response_0(
    OpticsRec_3192f450 var_o,
    wp::vec_t<3, wp::float32> var_local)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    const wp::float32 var_4 = 0.0;
    wp::int32* var_5;
    const wp::int32 var_6 = 1;
    bool var_7;
    wp::int32 var_8;
    const wp::float32 var_9 = 1.0;
    wp::float32 var_10;
    wp::float32* var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    const wp::int32 var_14 = 0;
    wp::float32 var_15;
    const wp::int32 var_16 = 0;
    wp::float32 var_17;
    wp::float32 var_18;
    const wp::int32 var_19 = 1;
    wp::float32 var_20;
    const wp::int32 var_21 = 1;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::int32* var_27;
    const wp::int32 var_28 = 1;
    bool var_29;
    wp::int32 var_30;
    const wp::int32 var_31 = 0;
    wp::float32 var_32;
    const wp::int32 var_33 = 1;
    wp::float32 var_34;
    const wp::int32 var_35 = 0;
    wp::float32 var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 0.0;
    bool var_39;
    const wp::float32 var_40 = 6.283185307179586;
    wp::float32 var_41;
    wp::float32 var_42;
    wp::int32* var_43;
    const wp::int32 var_44 = 1;
    wp::int32 var_45;
    wp::int32 var_46;
    const wp::int32 var_47 = 0;
    wp::int32 var_48;
    wp::array_t<wp::float32>* var_49;
    wp::int32* var_50;
    const wp::int32 var_51 = 1;
    wp::int32 var_52;
    wp::int32 var_53;
    wp::float32* var_54;
    wp::array_t<wp::float32> var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::array_t<wp::float32>* var_58;
    const wp::int32 var_59 = 0;
    wp::float32* var_60;
    wp::array_t<wp::float32> var_61;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::array_t<wp::float32>* var_64;
    const wp::int32 var_65 = 0;
    wp::float32* var_66;
    wp::array_t<wp::float32> var_67;
    bool var_68;
    wp::float32 var_69;
    wp::float32 var_70;
    wp::array_t<wp::float32>* var_71;
    const wp::int32 var_72 = 0;
    wp::float32* var_73;
    wp::array_t<wp::float32> var_74;
    wp::float32 var_75;
    wp::float32 var_76;
    wp::array_t<wp::float32>* var_77;
    wp::int32* var_78;
    const wp::int32 var_79 = 1;
    wp::int32 var_80;
    wp::int32 var_81;
    wp::float32* var_82;
    wp::array_t<wp::float32> var_83;
    bool var_84;
    wp::float32 var_85;
    wp::array_t<wp::float32>* var_86;
    wp::int32* var_87;
    wp::int32 var_88;
    wp::array_t<wp::float32> var_89;
    wp::int32 var_90;
    const wp::int32 var_91 = 1;
    wp::int32 var_92;
    wp::array_t<wp::float32>* var_93;
    wp::float32* var_94;
    wp::array_t<wp::float32> var_95;
    wp::float32 var_96;
    wp::float32 var_97;
    wp::array_t<wp::float32>* var_98;
    wp::float32* var_99;
    wp::array_t<wp::float32> var_100;
    wp::float32 var_101;
    wp::float32 var_102;
    wp::int32 var_103;
    wp::int32 var_104;
    wp::float32 var_105;
    wp::float32 var_106;
    wp::int32 var_107;
    wp::int32 var_108;
    wp::float32 var_109;
    wp::float32 var_110;
    wp::float32 var_111;
    wp::float32 var_112;
    wp::float32 var_113;
    const wp::float32 var_114 = 0.0;
    const wp::float32 var_115 = 1.0;
    wp::float32 var_116;
    wp::float32 var_117;
    wp::float32 var_118;
    wp::float32 var_119;
    wp::float32 var_120;
    wp::float32 var_121;
    //---------
    // forward
    // def optics_response(o: OpticsRec, local: wp.vec3) -> float:                            <L 123>
    // z = local[2]                                                                           <L 125>
    var_1 = wp::extract(var_local, var_0);
    // if z <= 0.0:                                                                           <L 126>
    var_3 = (var_1 <= var_2);
    if (var_3) {
        // return 0.0                                                                         <L 127>
        return var_4;
    }
    // if o.kind == 1:                                                                        <L 128>
    var_5 = &((var_o).kind);
    var_8 = wp::load(var_5);
    var_7 = (var_8 == var_6);
    if (var_7) {
        // return wp.pow(wp.min(z, 1.0), o.exponent)                                          <L 129>
        var_10 = wp::min(var_1, var_9);
        var_11 = &((var_o).exponent);
        var_13 = wp::load(var_11);
        var_12 = wp::pow(var_10, var_13);
        return var_12;
    }
    // s = wp.sqrt(local[0] * local[0] + local[1] * local[1])                                 <L 130>
    var_15 = wp::extract(var_local, var_14);
    var_17 = wp::extract(var_local, var_16);
    var_18 = wp::mul(var_15, var_17);
    var_20 = wp::extract(var_local, var_19);
    var_22 = wp::extract(var_local, var_21);
    var_23 = wp::mul(var_20, var_22);
    var_24 = wp::add(var_18, var_23);
    var_25 = wp::sqrt(var_24);
    // theta = wp.atan2(s, z)  # accurate near the normal, where acos(z) is not               <L 131>
    var_26 = wp::atan2(var_25, var_1);
    // if o.n_phi <= 1:                                                                       <L 132>
    var_27 = &((var_o).n_phi);
    var_30 = wp::load(var_27);
    var_29 = (var_30 <= var_28);
    if (var_29) {
        // return table_column(o, 0, theta)                                                   <L 133>
        var_32 = table_column_0(var_o, var_31, var_26);
        return var_32;
    }
    // phi = wp.atan2(local[1], local[0])                                                     <L 134>
    var_34 = wp::extract(var_local, var_33);
    var_36 = wp::extract(var_local, var_35);
    var_37 = wp::atan2(var_34, var_36);
    // if phi < 0.0:                                                                          <L 135>
    var_39 = (var_37 < var_38);
    if (var_39) {
        // phi = phi + TWO_PI                                                                 <L 136>
        var_41 = wp::add(var_37, var_40);
    }
    var_42 = wp::where(var_39, var_41, var_37);
    // k0 = o.n_phi - 1                                                                       <L 138>
    var_43 = &((var_o).n_phi);
    var_46 = wp::load(var_43);
    var_45 = wp::sub(var_46, var_44);
    // k1 = int(0)                                                                            <L 139>
    var_48 = wp::int(var_47);
    // p0 = o.phi[o.n_phi - 1]                                                                <L 140>
    var_49 = &((var_o).phi);
    var_50 = &((var_o).n_phi);
    var_53 = wp::load(var_50);
    var_52 = wp::sub(var_53, var_51);
    var_55 = wp::load(var_49);
    var_54 = wp::address(var_55, var_52);
    var_57 = wp::load(var_54);
    var_56 = wp::copy(var_57);
    // p1 = o.phi[0] + TWO_PI                                                                 <L 141>
    var_58 = &((var_o).phi);
    var_61 = wp::load(var_58);
    var_60 = wp::address(var_61, var_59);
    var_63 = wp::load(var_60);
    var_62 = wp::add(var_63, var_40);
    // if phi < o.phi[0]:                                                                     <L 142>
    var_64 = &((var_o).phi);
    var_67 = wp::load(var_64);
    var_66 = wp::address(var_67, var_65);
    var_69 = wp::load(var_66);
    var_68 = (var_42 < var_69);
    if (var_68) {
        // p0 = p0 - TWO_PI                                                                   <L 143>
        var_70 = wp::sub(var_56, var_40);
        // p1 = o.phi[0]                                                                      <L 144>
        var_71 = &((var_o).phi);
        var_74 = wp::load(var_71);
        var_73 = wp::address(var_74, var_72);
        var_76 = wp::load(var_73);
        var_75 = wp::copy(var_76);
    }
    if (!var_68) {
        // elif phi < o.phi[o.n_phi - 1]:                                                     <L 145>
        var_77 = &((var_o).phi);
        var_78 = &((var_o).n_phi);
        var_81 = wp::load(var_78);
        var_80 = wp::sub(var_81, var_79);
        var_83 = wp::load(var_77);
        var_82 = wp::address(var_83, var_80);
        var_85 = wp::load(var_82);
        var_84 = (var_42 < var_85);
        if (var_84) {
            // k0 = knot_interval(o.phi, o.n_phi, phi)                                        <L 146>
            var_86 = &((var_o).phi);
            var_87 = &((var_o).n_phi);
            var_89 = wp::load(var_86);
            var_90 = wp::load(var_87);
            var_88 = knot_interval_0(var_89, var_90, var_42);
            // k1 = k0 + 1                                                                    <L 147>
            var_92 = wp::add(var_88, var_91);
            // p0 = o.phi[k0]                                                                 <L 148>
            var_93 = &((var_o).phi);
            var_95 = wp::load(var_93);
            var_94 = wp::address(var_95, var_88);
            var_97 = wp::load(var_94);
            var_96 = wp::copy(var_97);
            // p1 = o.phi[k1]                                                                 <L 149>
            var_98 = &((var_o).phi);
            var_100 = wp::load(var_98);
            var_99 = wp::address(var_100, var_92);
            var_102 = wp::load(var_99);
            var_101 = wp::copy(var_102);
        }
        var_103 = wp::where(var_84, var_88, var_45);
        var_104 = wp::where(var_84, var_92, var_48);
        var_105 = wp::where(var_84, var_96, var_56);
        var_106 = wp::where(var_84, var_101, var_62);
    }
    var_107 = wp::where(var_68, var_45, var_103);
    var_108 = wp::where(var_68, var_48, var_104);
    var_109 = wp::where(var_68, var_70, var_105);
    var_110 = wp::where(var_68, var_75, var_106);
    // f = wp.clamp((phi - p0) / (p1 - p0), 0.0, 1.0)                                         <L 150>
    var_111 = wp::sub(var_42, var_109);
    var_112 = wp::sub(var_110, var_109);
    var_113 = wp::div(var_111, var_112);
    var_116 = wp::clamp(var_113, var_114, var_115);
    // r0 = table_column(o, k0, theta)                                                        <L 151>
    var_117 = table_column_0(var_o, var_107, var_26);
    // r1 = table_column(o, k1, theta)                                                        <L 152>
    var_118 = table_column_0(var_o, var_108, var_26);
    // return r0 + f * (r1 - r0)                                                              <L 153>
    var_119 = wp::sub(var_118, var_117);
    var_120 = wp::mul(var_116, var_119);
    var_121 = wp::add(var_117, var_120);
    return var_121;
}


// /work/main/simulator/kernels/optics.py:156
static OpticsSample_915df1ad sample_optics_0(
    OpticsRec_3192f450 var_o,
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    OpticsSample_915df1ad var_0;
    const wp::float32 var_1 = 1.0;
    wp::float32 var_2;
    const wp::float32 var_3 = 6.283185307179586;
    const wp::int32 var_4 = 1;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::int32* var_7;
    const wp::int32 var_8 = 1;
    bool var_9;
    wp::int32 var_10;
    const wp::int32 var_11 = 0;
    wp::float32 var_12;
    const wp::float32 var_13 = 1e-30;
    wp::float32 var_14;
    const wp::float32 var_15 = 1.0;
    wp::float32* var_16;
    const wp::float32 var_17 = 1.0;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::array_t<wp::float32>* var_22;
    wp::array_t<wp::float32>* var_23;
    wp::int32* var_24;
    wp::int32* var_25;
    Dist2DSample_164324b3 var_26;
    wp::array_t<wp::float32> var_27;
    wp::array_t<wp::float32> var_28;
    wp::int32 var_29;
    wp::int32 var_30;
    wp::int32* var_31;
    wp::int32* var_32;
    wp::int32 var_33;
    wp::int32 var_34;
    wp::int32 var_35;
    wp::vec_t<2, wp::float32>* var_36;
    const wp::int32 var_37 = 1;
    wp::float32 var_38;
    wp::vec_t<2, wp::float32> var_39;
    wp::int32* var_40;
    wp::float32 var_41;
    wp::int32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32 var_45;
    const wp::float32 var_46 = 0.0;
    const wp::float32 var_47 = 1.0;
    wp::float32 var_48;
    wp::array_t<wp::float32>* var_49;
    wp::float32* var_50;
    wp::array_t<wp::float32> var_51;
    wp::array_t<wp::float32>* var_52;
    wp::float32* var_53;
    wp::array_t<wp::float32> var_54;
    wp::float32 var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32 var_58;
    wp::vec_t<2, wp::float32>* var_59;
    const wp::int32 var_60 = 0;
    wp::float32 var_61;
    wp::vec_t<2, wp::float32> var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    wp::float32 var_65;
    const wp::float32 var_66 = 0.0;
    const wp::float32 var_67 = 1.0;
    wp::float32 var_68;
    wp::float32 var_69;
    wp::float32 var_70;
    wp::float32 var_71;
    wp::float32 var_72;
    wp::float32 var_73;
    wp::float32 var_74;
    wp::float32 var_75;
    wp::vec_t<3, wp::float32> var_76;
    wp::int32* var_77;
    const wp::int32 var_78 = 1;
    bool var_79;
    wp::int32 var_80;
    wp::vec_t<3, wp::float32>* var_81;
    wp::float32 var_82;
    wp::vec_t<3, wp::float32> var_83;
    wp::float32* var_84;
    wp::int32* var_85;
    wp::float32 var_86;
    wp::int32 var_87;
    wp::array_t<wp::float32>* var_88;
    wp::float32* var_89;
    wp::array_t<wp::float32> var_90;
    wp::float32 var_91;
    wp::float32 var_92;
    wp::float32 var_93;
    wp::float32 var_94;
    wp::float32 var_95;
    const wp::float32 var_96 = 0.0;
    wp::float32* var_97;
    const wp::float32 var_98 = 0.0;
    bool var_99;
    wp::float32 var_100;
    wp::vec_t<3, wp::float32>* var_101;
    wp::float32 var_102;
    wp::vec_t<3, wp::float32> var_103;
    wp::float32* var_104;
    wp::float32 var_105;
    wp::float32 var_106;
    //---------
    // forward
    // def sample_optics(o: OpticsRec, u: wp.vec2) -> OpticsSample:                           <L 157>
    // s = OpticsSample()                                                                     <L 160>
    var_0 = OpticsSample_915df1ad();
    // mu = float(1.0)                                                                        <L 161>
    var_2 = wp::float(var_1);
    // phi = TWO_PI * u[1]                                                                    <L 162>
    var_5 = wp::extract(var_u, var_4);
    var_6 = wp::mul(var_3, var_5);
    // if o.kind == 1:                                                                        <L 163>
    var_7 = &((var_o).kind);
    var_10 = wp::load(var_7);
    var_9 = (var_10 == var_8);
    if (var_9) {
        // mu = wp.pow(wp.max(u[0], 1.0e-30), 1.0 / (o.exponent + 1.0))                       <L 164>
        var_12 = wp::extract(var_u, var_11);
        var_14 = wp::max(var_12, var_13);
        var_16 = &((var_o).exponent);
        var_19 = wp::load(var_16);
        var_18 = wp::add(var_19, var_17);
        var_20 = wp::div(var_15, var_18);
        var_21 = wp::pow(var_14, var_20);
    }
    if (!var_9) {
        // ds = sample_piecewise_2d(o.marg, o.cond, o.cols, o.rows, u)  # u[0] the θ bin, u[1] the φ bin       <L 166>
        var_22 = &((var_o).marg);
        var_23 = &((var_o).cond);
        var_24 = &((var_o).cols);
        var_25 = &((var_o).rows);
        var_27 = wp::load(var_22);
        var_28 = wp::load(var_23);
        var_29 = wp::load(var_24);
        var_30 = wp::load(var_25);
        var_26 = sample_piecewise_2d_0(var_27, var_28, var_29, var_30, var_u);
        // j = ds.texel // o.cols                                                             <L 167>
        var_31 = &((var_26).texel);
        var_32 = &((var_o).cols);
        var_34 = wp::load(var_31);
        var_35 = wp::load(var_32);
        var_33 = wp::floordiv(var_34, var_35);
        // fv = wp.clamp(ds.uv[1] * float(o.rows) - float(j), 0.0, 1.0)                       <L 168>
        var_36 = &((var_26).uv);
        var_39 = wp::load(var_36);
        var_38 = wp::extract(var_39, var_37);
        var_40 = &((var_o).rows);
        var_42 = wp::load(var_40);
        var_41 = wp::float(var_42);
        var_43 = wp::mul(var_38, var_41);
        var_44 = wp::float(var_33);
        var_45 = wp::sub(var_43, var_44);
        var_48 = wp::clamp(var_45, var_46, var_47);
        // mu = o.row_mu[j] - fv * o.row_dmu[j]                                               <L 169>
        var_49 = &((var_o).row_mu);
        var_51 = wp::load(var_49);
        var_50 = wp::address(var_51, var_33);
        var_52 = &((var_o).row_dmu);
        var_54 = wp::load(var_52);
        var_53 = wp::address(var_54, var_33);
        var_56 = wp::load(var_53);
        var_55 = wp::mul(var_48, var_56);
        var_58 = wp::load(var_50);
        var_57 = wp::sub(var_58, var_55);
        // phi = TWO_PI * ds.uv[0]                                                            <L 170>
        var_59 = &((var_26).uv);
        var_62 = wp::load(var_59);
        var_61 = wp::extract(var_62, var_60);
        var_63 = wp::mul(var_3, var_61);
    }
    var_64 = wp::where(var_9, var_21, var_57);
    var_65 = wp::where(var_9, var_6, var_63);
    // sin_t = wp.sqrt(wp.max(0.0, 1.0 - mu * mu))                                            <L 171>
    var_68 = wp::mul(var_64, var_64);
    var_69 = wp::sub(var_67, var_68);
    var_70 = wp::max(var_66, var_69);
    var_71 = wp::sqrt(var_70);
    // s.local = wp.vec3(sin_t * wp.cos(phi), sin_t * wp.sin(phi), mu)                        <L 172>
    var_72 = wp::cos(var_65);
    var_73 = wp::mul(var_71, var_72);
    var_74 = wp::sin(var_65);
    var_75 = wp::mul(var_71, var_74);
    var_76 = wp::vec_t<3, wp::float32>(var_73, var_75, var_64);
    var_0.local = var_76;
    // if o.kind == 1:                                                                        <L 173>
    var_77 = &((var_o).kind);
    var_80 = wp::load(var_77);
    var_79 = (var_80 == var_78);
    if (var_79) {
        // s.pdf = pdf_optics(o, s.local)                                                     <L 174>
        var_81 = &((var_0).local);
        var_83 = wp::load(var_81);
        var_82 = pdf_optics_0(var_o, var_83);
        var_0.pdf = var_82;
    }
    if (!var_79) {
        // s.pdf = ds.pdf / (float(o.rows) * o.row_dmu[j] * TWO_PI)                           <L 176>
        var_84 = &((var_26).pdf);
        var_85 = &((var_o).rows);
        var_87 = wp::load(var_85);
        var_86 = wp::float(var_87);
        var_88 = &((var_o).row_dmu);
        var_90 = wp::load(var_88);
        var_89 = wp::address(var_90, var_33);
        var_92 = wp::load(var_89);
        var_91 = wp::mul(var_86, var_92);
        var_93 = wp::mul(var_91, var_3);
        var_95 = wp::load(var_84);
        var_94 = wp::div(var_95, var_93);
        var_0.pdf = var_94;
    }
    // s.weight = 0.0                                                                         <L 177>
    var_0.weight = var_96;
    // if s.pdf > 0.0:                                                                        <L 178>
    var_97 = &((var_0).pdf);
    var_100 = wp::load(var_97);
    var_99 = (var_100 > var_98);
    if (var_99) {
        // s.weight = optics_response(o, s.local) / s.pdf                                     <L 179>
        var_101 = &((var_0).local);
        var_103 = wp::load(var_101);
        var_102 = optics_response_0(var_o, var_103);
        var_104 = &((var_0).pdf);
        var_106 = wp::load(var_104);
        var_105 = wp::div(var_102, var_106);
        var_0.weight = var_105;
    }
    // return s                                                                               <L 180>
    return var_0;
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


// /work/main/simulator/kernels/optics.py:183
static void adj_pdf_optics_0(
    OpticsRec_3192f450 var_o,
    wp::vec_t<3, wp::float32> var_local,
    OpticsRec_3192f450 & adj_o,
    wp::vec_t<3, wp::float32> & adj_local,
    wp::float32 & adj_ret)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    const wp::float32 var_4 = 0.0;
    wp::int32* var_5;
    const wp::int32 var_6 = 1;
    bool var_7;
    wp::int32 var_8;
    wp::float32* var_9;
    const wp::float32 var_10 = 1.0;
    wp::float32 var_11;
    wp::float32 var_12;
    const wp::float32 var_13 = 6.283185307179586;
    wp::float32 var_14;
    const wp::float32 var_15 = 1.0;
    wp::float32 var_16;
    wp::float32* var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    const wp::int32 var_21 = 0;
    wp::float32 var_22;
    const wp::int32 var_23 = 0;
    wp::float32 var_24;
    wp::float32 var_25;
    const wp::int32 var_26 = 1;
    wp::float32 var_27;
    const wp::int32 var_28 = 1;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32 var_33;
    wp::float32* var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::int32 var_37;
    wp::int32* var_38;
    bool var_39;
    wp::int32 var_40;
    const wp::float32 var_41 = 0.0;
    wp::array_t<wp::float32>* var_42;
    wp::float32* var_43;
    wp::array_t<wp::float32> var_44;
    wp::float32 var_45;
    wp::float32 var_46;
    wp::array_t<wp::float32>* var_47;
    wp::float32* var_48;
    wp::array_t<wp::float32> var_49;
    wp::float32 var_50;
    wp::float32 var_51;
    const wp::float32 var_52 = 0.0;
    const wp::float32 var_53 = 0.99999994;
    wp::float32 var_54;
    const wp::int32 var_55 = 1;
    wp::float32 var_56;
    const wp::int32 var_57 = 0;
    wp::float32 var_58;
    wp::float32 var_59;
    const wp::float32 var_60 = 0.0;
    bool var_61;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    const wp::float32 var_65 = 0.0;
    const wp::float32 var_66 = 0.99999994;
    wp::float32 var_67;
    wp::float32 var_68;
    wp::float32 var_69;
    wp::int32* var_70;
    wp::float32 var_71;
    wp::int32 var_72;
    wp::float32 var_73;
    wp::vec_t<2, wp::float32> var_74;
    wp::array_t<wp::float32>* var_75;
    wp::array_t<wp::float32>* var_76;
    wp::int32* var_77;
    wp::int32* var_78;
    wp::float32 var_79;
    wp::array_t<wp::float32> var_80;
    wp::array_t<wp::float32> var_81;
    wp::int32 var_82;
    wp::int32 var_83;
    wp::int32* var_84;
    wp::float32 var_85;
    wp::int32 var_86;
    wp::array_t<wp::float32>* var_87;
    wp::float32* var_88;
    wp::array_t<wp::float32> var_89;
    wp::float32 var_90;
    wp::float32 var_91;
    wp::float32 var_92;
    wp::float32 var_93;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    bool adj_3 = {};
    wp::float32 adj_4 = {};
    wp::int32 adj_5 = {};
    wp::int32 adj_6 = {};
    bool adj_7 = {};
    wp::int32 adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::float32 adj_13 = {};
    wp::float32 adj_14 = {};
    wp::float32 adj_15 = {};
    wp::float32 adj_16 = {};
    wp::float32 adj_17 = {};
    wp::float32 adj_18 = {};
    wp::float32 adj_19 = {};
    wp::float32 adj_20 = {};
    wp::int32 adj_21 = {};
    wp::float32 adj_22 = {};
    wp::int32 adj_23 = {};
    wp::float32 adj_24 = {};
    wp::float32 adj_25 = {};
    wp::int32 adj_26 = {};
    wp::float32 adj_27 = {};
    wp::int32 adj_28 = {};
    wp::float32 adj_29 = {};
    wp::float32 adj_30 = {};
    wp::float32 adj_31 = {};
    wp::float32 adj_32 = {};
    wp::float32 adj_33 = {};
    wp::float32 adj_34 = {};
    wp::float32 adj_35 = {};
    wp::float32 adj_36 = {};
    wp::int32 adj_37 = {};
    wp::int32 adj_38 = {};
    bool adj_39 = {};
    wp::int32 adj_40 = {};
    wp::float32 adj_41 = {};
    wp::array_t<wp::float32> adj_42 = {};
    wp::float32 adj_43 = {};
    wp::array_t<wp::float32> adj_44 = {};
    wp::float32 adj_45 = {};
    wp::float32 adj_46 = {};
    wp::array_t<wp::float32> adj_47 = {};
    wp::float32 adj_48 = {};
    wp::array_t<wp::float32> adj_49 = {};
    wp::float32 adj_50 = {};
    wp::float32 adj_51 = {};
    wp::float32 adj_52 = {};
    wp::float32 adj_53 = {};
    wp::float32 adj_54 = {};
    wp::int32 adj_55 = {};
    wp::float32 adj_56 = {};
    wp::int32 adj_57 = {};
    wp::float32 adj_58 = {};
    wp::float32 adj_59 = {};
    wp::float32 adj_60 = {};
    bool adj_61 = {};
    wp::float32 adj_62 = {};
    wp::float32 adj_63 = {};
    wp::float32 adj_64 = {};
    wp::float32 adj_65 = {};
    wp::float32 adj_66 = {};
    wp::float32 adj_67 = {};
    wp::float32 adj_68 = {};
    wp::float32 adj_69 = {};
    wp::int32 adj_70 = {};
    wp::float32 adj_71 = {};
    wp::int32 adj_72 = {};
    wp::float32 adj_73 = {};
    wp::vec_t<2, wp::float32> adj_74 = {};
    wp::array_t<wp::float32> adj_75 = {};
    wp::array_t<wp::float32> adj_76 = {};
    wp::int32 adj_77 = {};
    wp::int32 adj_78 = {};
    wp::float32 adj_79 = {};
    wp::array_t<wp::float32> adj_80 = {};
    wp::array_t<wp::float32> adj_81 = {};
    wp::int32 adj_82 = {};
    wp::int32 adj_83 = {};
    wp::int32 adj_84 = {};
    wp::float32 adj_85 = {};
    wp::int32 adj_86 = {};
    wp::array_t<wp::float32> adj_87 = {};
    wp::float32 adj_88 = {};
    wp::array_t<wp::float32> adj_89 = {};
    wp::float32 adj_90 = {};
    wp::float32 adj_91 = {};
    wp::float32 adj_92 = {};
    wp::float32 adj_93 = {};
    //---------
    // forward
    // def pdf_optics(o: OpticsRec, local: wp.vec3) -> float:                                 <L 184>
    // z = local[2]                                                                           <L 186>
    var_1 = wp::extract(var_local, var_0);
    // if z <= 0.0:                                                                           <L 187>
    var_3 = (var_1 <= var_2);
    if (var_3) {
        // return 0.0                                                                         <L 188>
        goto label0;
    }
    // if o.kind == 1:                                                                        <L 189>
    var_5 = &((var_o).kind);
    var_8 = wp::load(var_5);
    var_7 = (var_8 == var_6);
    if (var_7) {
        // return (o.exponent + 1.0) / TWO_PI * wp.pow(wp.min(z, 1.0), o.exponent)            <L 190>
        var_9 = &((var_o).exponent);
        var_12 = wp::load(var_9);
        var_11 = wp::add(var_12, var_10);
        var_14 = wp::div(var_11, var_13);
        var_16 = wp::min(var_1, var_15);
        var_17 = &((var_o).exponent);
        var_19 = wp::load(var_17);
        var_18 = wp::pow(var_16, var_19);
        var_20 = wp::mul(var_14, var_18);
        goto label1;
    }
    // theta = wp.atan2(wp.sqrt(local[0] * local[0] + local[1] * local[1]), z)                <L 191>
    var_22 = wp::extract(var_local, var_21);
    var_24 = wp::extract(var_local, var_23);
    var_25 = wp::mul(var_22, var_24);
    var_27 = wp::extract(var_local, var_26);
    var_29 = wp::extract(var_local, var_28);
    var_30 = wp::mul(var_27, var_29);
    var_31 = wp::add(var_25, var_30);
    var_32 = wp::sqrt(var_31);
    var_33 = wp::atan2(var_32, var_1);
    // j = int(theta / o.d_theta)                                                             <L 192>
    var_34 = &((var_o).d_theta);
    var_36 = wp::load(var_34);
    var_35 = wp::div(var_33, var_36);
    var_37 = wp::int(var_35);
    // if j >= o.rows:                                                                        <L 193>
    var_38 = &((var_o).rows);
    var_40 = wp::load(var_38);
    var_39 = (var_37 >= var_40);
    if (var_39) {
        // return 0.0                                                                         <L 194>
        goto label2;
    }
    // fv = wp.clamp((o.row_mu[j] - z) / o.row_dmu[j], 0.0, 0.99999994)                       <L 195>
    var_42 = &((var_o).row_mu);
    var_44 = wp::load(var_42);
    var_43 = wp::address(var_44, var_37);
    var_46 = wp::load(var_43);
    var_45 = wp::sub(var_46, var_1);
    var_47 = &((var_o).row_dmu);
    var_49 = wp::load(var_47);
    var_48 = wp::address(var_49, var_37);
    var_51 = wp::load(var_48);
    var_50 = wp::div(var_45, var_51);
    var_54 = wp::clamp(var_50, var_52, var_53);
    // phi = wp.atan2(local[1], local[0])                                                     <L 196>
    var_56 = wp::extract(var_local, var_55);
    var_58 = wp::extract(var_local, var_57);
    var_59 = wp::atan2(var_56, var_58);
    // if phi < 0.0:                                                                          <L 197>
    var_61 = (var_59 < var_60);
    if (var_61) {
        // phi = phi + TWO_PI                                                                 <L 198>
        var_62 = wp::add(var_59, var_13);
    }
    var_63 = wp::where(var_61, var_62, var_59);
    // uv = wp.vec2(wp.clamp(phi / TWO_PI, 0.0, 0.99999994), (float(j) + fv) / float(o.rows))       <L 199>
    var_64 = wp::div(var_63, var_13);
    var_67 = wp::clamp(var_64, var_65, var_66);
    var_68 = wp::float(var_37);
    var_69 = wp::add(var_68, var_54);
    var_70 = &((var_o).rows);
    var_72 = wp::load(var_70);
    var_71 = wp::float(var_72);
    var_73 = wp::div(var_69, var_71);
    var_74 = wp::vec_t<2, wp::float32>(var_67, var_73);
    // return pdf_piecewise_2d(o.marg, o.cond, o.cols, o.rows, uv) / (float(o.rows) * o.row_dmu[j] * TWO_PI)       <L 200>
    var_75 = &((var_o).marg);
    var_76 = &((var_o).cond);
    var_77 = &((var_o).cols);
    var_78 = &((var_o).rows);
    var_80 = wp::load(var_75);
    var_81 = wp::load(var_76);
    var_82 = wp::load(var_77);
    var_83 = wp::load(var_78);
    var_79 = pdf_piecewise_2d_0(var_80, var_81, var_82, var_83, var_74);
    var_84 = &((var_o).rows);
    var_86 = wp::load(var_84);
    var_85 = wp::float(var_86);
    var_87 = &((var_o).row_dmu);
    var_89 = wp::load(var_87);
    var_88 = wp::address(var_89, var_37);
    var_91 = wp::load(var_88);
    var_90 = wp::mul(var_85, var_91);
    var_92 = wp::mul(var_90, var_13);
    var_93 = wp::div(var_79, var_92);
    goto label3;
    //---------
    // reverse
    label3:;
    adj_93 += adj_ret;
    wp::adj_div(var_79, var_92, var_93, adj_79, adj_92, adj_93);
    wp::adj_mul(var_90, var_13, adj_90, adj_13, adj_92);
    wp::adj_mul(var_85, var_91, adj_85, adj_88, adj_90);
    wp::adj_address(var_89, var_37, adj_87, adj_37, adj_88);
    adj_o.row_dmu = adj_87;
    wp::adj_float(var_86, adj_84, adj_85);
    adj_o.rows = adj_84;
    adj_pdf_piecewise_2d_0(var_80, var_81, var_82, var_83, var_74, adj_75, adj_76, adj_77, adj_78, adj_74, adj_79);
    adj_o.rows = adj_78;
    adj_o.cols = adj_77;
    adj_o.cond = adj_76;
    adj_o.marg = adj_75;
    // adj: return pdf_piecewise_2d(o.marg, o.cond, o.cols, o.rows, uv) / (float(o.rows) * o.row_dmu[j] * TWO_PI)  <L 200>
    wp::adj_vec_t(var_67, var_73, adj_67, adj_73, adj_74);
    wp::adj_div(var_69, var_71, var_73, adj_69, adj_71, adj_73);
    wp::adj_float(var_72, adj_70, adj_71);
    adj_o.rows = adj_70;
    wp::adj_add(var_68, var_54, adj_68, adj_54, adj_69);
    wp::adj_float(var_37, adj_37, adj_68);
    wp::adj_clamp(var_64, var_65, var_66, adj_64, adj_65, adj_66, adj_67);
    wp::adj_div(var_63, var_13, var_64, adj_63, adj_13, adj_64);
    // adj: uv = wp.vec2(wp.clamp(phi / TWO_PI, 0.0, 0.99999994), (float(j) + fv) / float(o.rows))  <L 199>
    wp::adj_where(var_61, var_62, var_59, adj_61, adj_62, adj_59, adj_63);
    if (var_61) {
        wp::adj_add(var_59, var_13, adj_59, adj_13, adj_62);
        // adj: phi = phi + TWO_PI                                                            <L 198>
    }
    // adj: if phi < 0.0:                                                                     <L 197>
    wp::adj_atan2(var_56, var_58, adj_56, adj_58, adj_59);
    wp::adj_extract(var_local, var_57, adj_local, adj_57, adj_58);
    wp::adj_extract(var_local, var_55, adj_local, adj_55, adj_56);
    // adj: phi = wp.atan2(local[1], local[0])                                                <L 196>
    wp::adj_clamp(var_50, var_52, var_53, adj_50, adj_52, adj_53, adj_54);
    wp::adj_div(var_45, var_51, var_50, adj_45, adj_48, adj_50);
    wp::adj_address(var_49, var_37, adj_47, adj_37, adj_48);
    adj_o.row_dmu = adj_47;
    wp::adj_sub(var_46, var_1, adj_43, adj_1, adj_45);
    wp::adj_address(var_44, var_37, adj_42, adj_37, adj_43);
    adj_o.row_mu = adj_42;
    // adj: fv = wp.clamp((o.row_mu[j] - z) / o.row_dmu[j], 0.0, 0.99999994)                  <L 195>
    if (var_39) {
        label2:;
        adj_41 += adj_ret;
        // adj: return 0.0                                                                    <L 194>
    }
    adj_o.rows = adj_38;
    // adj: if j >= o.rows:                                                                   <L 193>
    wp::adj_div(var_33, var_36, var_35, adj_33, adj_34, adj_35);
    adj_o.d_theta += adj_34;
    // adj: j = int(theta / o.d_theta)                                                        <L 192>
    wp::adj_atan2(var_32, var_1, adj_32, adj_1, adj_33);
    wp::adj_sqrt(var_31, var_32, adj_31, adj_32);
    wp::adj_add(var_25, var_30, adj_25, adj_30, adj_31);
    wp::adj_mul(var_27, var_29, adj_27, adj_29, adj_30);
    wp::adj_extract(var_local, var_28, adj_local, adj_28, adj_29);
    wp::adj_extract(var_local, var_26, adj_local, adj_26, adj_27);
    wp::adj_mul(var_22, var_24, adj_22, adj_24, adj_25);
    wp::adj_extract(var_local, var_23, adj_local, adj_23, adj_24);
    wp::adj_extract(var_local, var_21, adj_local, adj_21, adj_22);
    // adj: theta = wp.atan2(wp.sqrt(local[0] * local[0] + local[1] * local[1]), z)           <L 191>
    if (var_7) {
        label1:;
        adj_20 += adj_ret;
        wp::adj_mul(var_14, var_18, adj_14, adj_18, adj_20);
        wp::adj_pow(var_16, var_19, var_18, adj_16, adj_17, adj_18);
        adj_o.exponent += adj_17;
        wp::adj_min(var_1, var_15, adj_1, adj_15, adj_16);
        wp::adj_div(var_11, var_13, var_14, adj_11, adj_13, adj_14);
        wp::adj_add(var_12, var_10, adj_9, adj_10, adj_11);
        adj_o.exponent += adj_9;
        // adj: return (o.exponent + 1.0) / TWO_PI * wp.pow(wp.min(z, 1.0), o.exponent)       <L 190>
    }
    adj_o.kind = adj_5;
    // adj: if o.kind == 1:                                                                   <L 189>
    if (var_3) {
        label0:;
        adj_4 += adj_ret;
        // adj: return 0.0                                                                    <L 188>
    }
    // adj: if z <= 0.0:                                                                      <L 187>
    wp::adj_extract(var_local, var_0, adj_local, adj_0, adj_1);
    // adj: z = local[2]                                                                      <L 186>
    // adj: def pdf_optics(o: OpticsRec, local: wp.vec3) -> float:                            <L 184>
    return;
}


// /work/main/simulator/kernels/optics.py:94
static void adj_knot_interval_0(
    wp::array_t<wp::float32> var_a,
    wp::int32 var_n,
    wp::float32 var_x,
    wp::array_t<wp::float32> & adj_a,
    wp::int32 & adj_n,
    wp::float32 & adj_x,
    wp::int32 & adj_ret)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::int32 var_1;
    const wp::int32 var_2 = 2;
    wp::int32 var_3;
    bool var_4;
    wp::int32 var_5;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    const wp::int32 var_8 = 2;
    wp::int32 var_9;
    wp::float32* var_10;
    bool var_11;
    wp::float32 var_12;
    wp::int32 var_13;
    const wp::int32 var_14 = 1;
    wp::int32 var_15;
    wp::int32 var_16;
    wp::int32 var_17;
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
    wp::float32 adj_10 = {};
    bool adj_11 = {};
    wp::float32 adj_12 = {};
    wp::int32 adj_13 = {};
    wp::int32 adj_14 = {};
    wp::int32 adj_15 = {};
    wp::int32 adj_16 = {};
    wp::int32 adj_17 = {};
    //---------
    // forward
    // def knot_interval(a: wp.array(dtype=float), n: int, x: float) -> int:                  <L 95>
    // lo = int(0)                                                                            <L 98>
    var_1 = wp::int(var_0);
    // hi = n - 2                                                                             <L 99>
    var_3 = wp::sub(var_n, var_2);
    // while lo < hi:                                                                         <L 100>
    // return lo                                                                              <L 106>
    goto label2;
    //---------
    // reverse
    label2:;
    adj_1 += adj_ret;
    // adj: return lo                                                                         <L 106>
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
        // mid = (lo + hi + 1) // 2                                                           <L 101>
        var_5 = wp::add(var_1, var_3);
        var_7 = wp::add(var_5, var_6);
        var_9 = wp::floordiv(var_7, var_8);
        // if a[mid] <= x:                                                                    <L 102>
        var_10 = wp::address(var_a, var_9);
        var_12 = wp::load(var_10);
        var_11 = (var_12 <= var_x);
        if (var_11) {
            // lo = mid                                                                       <L 103>
            var_13 = wp::copy(var_9);
        }
        if (!var_11) {
            // hi = mid - 1                                                                   <L 105>
            var_15 = wp::sub(var_9, var_14);
        }
        var_16 = wp::where(var_11, var_13, var_1);
        var_17 = wp::where(var_11, var_3, var_15);
        wp::assign(var_1, var_16);
        wp::assign(var_3, var_17);
        wp::adj_assign(var_3, var_17, adj_3, adj_17);
        wp::adj_assign(var_1, var_16, adj_1, adj_16);
        wp::adj_where(var_11, var_3, var_15, adj_11, adj_3, adj_15, adj_17);
        wp::adj_where(var_11, var_13, var_1, adj_11, adj_13, adj_1, adj_16);
        if (!var_11) {
            wp::adj_sub(var_9, var_14, adj_9, adj_14, adj_15);
            // adj: hi = mid - 1                                                              <L 105>
        }
        if (var_11) {
            wp::adj_copy(var_9, adj_9, adj_13);
            // adj: lo = mid                                                                  <L 103>
        }
        wp::adj_address(var_a, var_9, adj_a, adj_9, adj_10);
        // adj: if a[mid] <= x:                                                               <L 102>
        wp::adj_add(var_5, var_6, adj_5, adj_6, adj_7);
        wp::adj_add(var_1, var_3, adj_1, adj_3, adj_5);
        // adj: mid = (lo + hi + 1) // 2                                                      <L 101>
    goto start_while_0;
    end_while_0:;
    // adj: while lo < hi:                                                                    <L 100>
    wp::adj_sub(var_n, var_2, adj_n, adj_2, adj_3);
    // adj: hi = n - 2                                                                        <L 99>
    // adj: lo = int(0)                                                                       <L 98>
    // adj: def knot_interval(a: wp.array(dtype=float), n: int, x: float) -> int:             <L 95>
    return;
}


// /work/main/simulator/kernels/optics.py:109
static void adj_table_column_0(
    OpticsRec_3192f450 var_o,
    wp::int32 var_k,
    wp::float32 var_theta,
    OpticsRec_3192f450 & adj_o,
    wp::int32 & adj_k,
    wp::float32 & adj_theta,
    wp::float32 & adj_ret)
{
    //---------
    // primal vars
    wp::array_t<wp::float32>* var_0;
    wp::int32* var_1;
    const wp::int32 var_2 = 1;
    wp::int32 var_3;
    wp::int32 var_4;
    wp::float32* var_5;
    wp::array_t<wp::float32> var_6;
    bool var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = 0.0;
    wp::array_t<wp::float32>* var_10;
    wp::int32* var_11;
    wp::int32 var_12;
    wp::array_t<wp::float32> var_13;
    wp::int32 var_14;
    wp::array_t<wp::float32>* var_15;
    wp::float32* var_16;
    wp::array_t<wp::float32> var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::array_t<wp::float32>* var_20;
    const wp::int32 var_21 = 1;
    wp::int32 var_22;
    wp::float32* var_23;
    wp::array_t<wp::float32> var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    const wp::float32 var_30 = 0.0;
    const wp::float32 var_31 = 1.0;
    wp::float32 var_32;
    wp::int32* var_33;
    wp::int32 var_34;
    wp::int32 var_35;
    wp::array_t<wp::float32>* var_36;
    wp::int32 var_37;
    wp::float32* var_38;
    wp::array_t<wp::float32> var_39;
    wp::array_t<wp::float32>* var_40;
    wp::int32 var_41;
    const wp::int32 var_42 = 1;
    wp::int32 var_43;
    wp::float32* var_44;
    wp::array_t<wp::float32> var_45;
    wp::array_t<wp::float32>* var_46;
    wp::int32 var_47;
    wp::float32* var_48;
    wp::array_t<wp::float32> var_49;
    wp::float32 var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::float32 var_55;
    //---------
    // dual vars
    wp::array_t<wp::float32> adj_0 = {};
    wp::int32 adj_1 = {};
    wp::int32 adj_2 = {};
    wp::int32 adj_3 = {};
    wp::int32 adj_4 = {};
    wp::float32 adj_5 = {};
    wp::array_t<wp::float32> adj_6 = {};
    bool adj_7 = {};
    wp::float32 adj_8 = {};
    wp::float32 adj_9 = {};
    wp::array_t<wp::float32> adj_10 = {};
    wp::int32 adj_11 = {};
    wp::int32 adj_12 = {};
    wp::array_t<wp::float32> adj_13 = {};
    wp::int32 adj_14 = {};
    wp::array_t<wp::float32> adj_15 = {};
    wp::float32 adj_16 = {};
    wp::array_t<wp::float32> adj_17 = {};
    wp::float32 adj_18 = {};
    wp::float32 adj_19 = {};
    wp::array_t<wp::float32> adj_20 = {};
    wp::int32 adj_21 = {};
    wp::int32 adj_22 = {};
    wp::float32 adj_23 = {};
    wp::array_t<wp::float32> adj_24 = {};
    wp::float32 adj_25 = {};
    wp::float32 adj_26 = {};
    wp::float32 adj_27 = {};
    wp::float32 adj_28 = {};
    wp::float32 adj_29 = {};
    wp::float32 adj_30 = {};
    wp::float32 adj_31 = {};
    wp::float32 adj_32 = {};
    wp::int32 adj_33 = {};
    wp::int32 adj_34 = {};
    wp::int32 adj_35 = {};
    wp::array_t<wp::float32> adj_36 = {};
    wp::int32 adj_37 = {};
    wp::float32 adj_38 = {};
    wp::array_t<wp::float32> adj_39 = {};
    wp::array_t<wp::float32> adj_40 = {};
    wp::int32 adj_41 = {};
    wp::int32 adj_42 = {};
    wp::int32 adj_43 = {};
    wp::float32 adj_44 = {};
    wp::array_t<wp::float32> adj_45 = {};
    wp::array_t<wp::float32> adj_46 = {};
    wp::int32 adj_47 = {};
    wp::float32 adj_48 = {};
    wp::array_t<wp::float32> adj_49 = {};
    wp::float32 adj_50 = {};
    wp::float32 adj_51 = {};
    wp::float32 adj_52 = {};
    wp::float32 adj_53 = {};
    wp::float32 adj_54 = {};
    wp::float32 adj_55 = {};
    //---------
    // forward
    // def table_column(o: OpticsRec, k: int, theta: float) -> float:                         <L 110>
    // if theta > o.theta[o.n_theta - 1]:                                                     <L 112>
    var_0 = &((var_o).theta);
    var_1 = &((var_o).n_theta);
    var_4 = wp::load(var_1);
    var_3 = wp::sub(var_4, var_2);
    var_6 = wp::load(var_0);
    var_5 = wp::address(var_6, var_3);
    var_8 = wp::load(var_5);
    var_7 = (var_theta > var_8);
    if (var_7) {
        // return 0.0                                                                         <L 113>
        goto label0;
    }
    // j = knot_interval(o.theta, o.n_theta, theta)                                           <L 114>
    var_10 = &((var_o).theta);
    var_11 = &((var_o).n_theta);
    var_13 = wp::load(var_10);
    var_14 = wp::load(var_11);
    var_12 = knot_interval_0(var_13, var_14, var_theta);
    // t0 = o.theta[j]                                                                        <L 115>
    var_15 = &((var_o).theta);
    var_17 = wp::load(var_15);
    var_16 = wp::address(var_17, var_12);
    var_19 = wp::load(var_16);
    var_18 = wp::copy(var_19);
    // t1 = o.theta[j + 1]                                                                    <L 116>
    var_20 = &((var_o).theta);
    var_22 = wp::add(var_12, var_21);
    var_24 = wp::load(var_20);
    var_23 = wp::address(var_24, var_22);
    var_26 = wp::load(var_23);
    var_25 = wp::copy(var_26);
    // f = wp.clamp((theta - t0) / (t1 - t0), 0.0, 1.0)                                       <L 117>
    var_27 = wp::sub(var_theta, var_18);
    var_28 = wp::sub(var_25, var_18);
    var_29 = wp::div(var_27, var_28);
    var_32 = wp::clamp(var_29, var_30, var_31);
    // base = k * o.n_theta                                                                   <L 118>
    var_33 = &((var_o).n_theta);
    var_35 = wp::load(var_33);
    var_34 = wp::mul(var_k, var_35);
    // return o.values[base + j] + f * (o.values[base + j + 1] - o.values[base + j])          <L 119>
    var_36 = &((var_o).values);
    var_37 = wp::add(var_34, var_12);
    var_39 = wp::load(var_36);
    var_38 = wp::address(var_39, var_37);
    var_40 = &((var_o).values);
    var_41 = wp::add(var_34, var_12);
    var_43 = wp::add(var_41, var_42);
    var_45 = wp::load(var_40);
    var_44 = wp::address(var_45, var_43);
    var_46 = &((var_o).values);
    var_47 = wp::add(var_34, var_12);
    var_49 = wp::load(var_46);
    var_48 = wp::address(var_49, var_47);
    var_51 = wp::load(var_44);
    var_52 = wp::load(var_48);
    var_50 = wp::sub(var_51, var_52);
    var_53 = wp::mul(var_32, var_50);
    var_55 = wp::load(var_38);
    var_54 = wp::add(var_55, var_53);
    goto label1;
    //---------
    // reverse
    label1:;
    adj_54 += adj_ret;
    wp::adj_add(var_55, var_53, adj_38, adj_53, adj_54);
    wp::adj_mul(var_32, var_50, adj_32, adj_50, adj_53);
    wp::adj_sub(var_51, var_52, adj_44, adj_48, adj_50);
    wp::adj_address(var_49, var_47, adj_46, adj_47, adj_48);
    wp::adj_add(var_34, var_12, adj_34, adj_12, adj_47);
    adj_o.values = adj_46;
    wp::adj_address(var_45, var_43, adj_40, adj_43, adj_44);
    wp::adj_add(var_41, var_42, adj_41, adj_42, adj_43);
    wp::adj_add(var_34, var_12, adj_34, adj_12, adj_41);
    adj_o.values = adj_40;
    wp::adj_address(var_39, var_37, adj_36, adj_37, adj_38);
    wp::adj_add(var_34, var_12, adj_34, adj_12, adj_37);
    adj_o.values = adj_36;
    // adj: return o.values[base + j] + f * (o.values[base + j + 1] - o.values[base + j])     <L 119>
    wp::adj_mul(var_k, var_35, adj_k, adj_33, adj_34);
    adj_o.n_theta = adj_33;
    // adj: base = k * o.n_theta                                                              <L 118>
    wp::adj_clamp(var_29, var_30, var_31, adj_29, adj_30, adj_31, adj_32);
    wp::adj_div(var_27, var_28, var_29, adj_27, adj_28, adj_29);
    wp::adj_sub(var_25, var_18, adj_25, adj_18, adj_28);
    wp::adj_sub(var_theta, var_18, adj_theta, adj_18, adj_27);
    // adj: f = wp.clamp((theta - t0) / (t1 - t0), 0.0, 1.0)                                  <L 117>
    wp::adj_copy(var_26, adj_23, adj_25);
    wp::adj_address(var_24, var_22, adj_20, adj_22, adj_23);
    wp::adj_add(var_12, var_21, adj_12, adj_21, adj_22);
    adj_o.theta = adj_20;
    // adj: t1 = o.theta[j + 1]                                                               <L 116>
    wp::adj_copy(var_19, adj_16, adj_18);
    wp::adj_address(var_17, var_12, adj_15, adj_12, adj_16);
    adj_o.theta = adj_15;
    // adj: t0 = o.theta[j]                                                                   <L 115>
    adj_knot_interval_0(var_13, var_14, var_theta, adj_10, adj_11, adj_theta, adj_12);
    adj_o.n_theta = adj_11;
    adj_o.theta = adj_10;
    // adj: j = knot_interval(o.theta, o.n_theta, theta)                                      <L 114>
    if (var_7) {
        label0:;
        adj_9 += adj_ret;
        // adj: return 0.0                                                                    <L 113>
    }
    wp::adj_address(var_6, var_3, adj_0, adj_3, adj_5);
    wp::adj_sub(var_4, var_2, adj_1, adj_2, adj_3);
    adj_o.n_theta = adj_1;
    adj_o.theta = adj_0;
    // adj: if theta > o.theta[o.n_theta - 1]:                                                <L 112>
    // adj: def table_column(o: OpticsRec, k: int, theta: float) -> float:                    <L 110>
    return;
}


// /work/main/simulator/kernels/optics.py:122
static void adj_optics_response_0(
    OpticsRec_3192f450 var_o,
    wp::vec_t<3, wp::float32> var_local,
    OpticsRec_3192f450 & adj_o,
    wp::vec_t<3, wp::float32> & adj_local,
    wp::float32 & adj_ret)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    const wp::float32 var_4 = 0.0;
    wp::int32* var_5;
    const wp::int32 var_6 = 1;
    bool var_7;
    wp::int32 var_8;
    const wp::float32 var_9 = 1.0;
    wp::float32 var_10;
    wp::float32* var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    const wp::int32 var_14 = 0;
    wp::float32 var_15;
    const wp::int32 var_16 = 0;
    wp::float32 var_17;
    wp::float32 var_18;
    const wp::int32 var_19 = 1;
    wp::float32 var_20;
    const wp::int32 var_21 = 1;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::int32* var_27;
    const wp::int32 var_28 = 1;
    bool var_29;
    wp::int32 var_30;
    const wp::int32 var_31 = 0;
    wp::float32 var_32;
    const wp::int32 var_33 = 1;
    wp::float32 var_34;
    const wp::int32 var_35 = 0;
    wp::float32 var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 0.0;
    bool var_39;
    const wp::float32 var_40 = 6.283185307179586;
    wp::float32 var_41;
    wp::float32 var_42;
    wp::int32* var_43;
    const wp::int32 var_44 = 1;
    wp::int32 var_45;
    wp::int32 var_46;
    const wp::int32 var_47 = 0;
    wp::int32 var_48;
    wp::array_t<wp::float32>* var_49;
    wp::int32* var_50;
    const wp::int32 var_51 = 1;
    wp::int32 var_52;
    wp::int32 var_53;
    wp::float32* var_54;
    wp::array_t<wp::float32> var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::array_t<wp::float32>* var_58;
    const wp::int32 var_59 = 0;
    wp::float32* var_60;
    wp::array_t<wp::float32> var_61;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::array_t<wp::float32>* var_64;
    const wp::int32 var_65 = 0;
    wp::float32* var_66;
    wp::array_t<wp::float32> var_67;
    bool var_68;
    wp::float32 var_69;
    wp::float32 var_70;
    wp::array_t<wp::float32>* var_71;
    const wp::int32 var_72 = 0;
    wp::float32* var_73;
    wp::array_t<wp::float32> var_74;
    wp::float32 var_75;
    wp::float32 var_76;
    wp::array_t<wp::float32>* var_77;
    wp::int32* var_78;
    const wp::int32 var_79 = 1;
    wp::int32 var_80;
    wp::int32 var_81;
    wp::float32* var_82;
    wp::array_t<wp::float32> var_83;
    bool var_84;
    wp::float32 var_85;
    wp::array_t<wp::float32>* var_86;
    wp::int32* var_87;
    wp::int32 var_88;
    wp::array_t<wp::float32> var_89;
    wp::int32 var_90;
    const wp::int32 var_91 = 1;
    wp::int32 var_92;
    wp::array_t<wp::float32>* var_93;
    wp::float32* var_94;
    wp::array_t<wp::float32> var_95;
    wp::float32 var_96;
    wp::float32 var_97;
    wp::array_t<wp::float32>* var_98;
    wp::float32* var_99;
    wp::array_t<wp::float32> var_100;
    wp::float32 var_101;
    wp::float32 var_102;
    wp::int32 var_103;
    wp::int32 var_104;
    wp::float32 var_105;
    wp::float32 var_106;
    wp::int32 var_107;
    wp::int32 var_108;
    wp::float32 var_109;
    wp::float32 var_110;
    wp::float32 var_111;
    wp::float32 var_112;
    wp::float32 var_113;
    const wp::float32 var_114 = 0.0;
    const wp::float32 var_115 = 1.0;
    wp::float32 var_116;
    wp::float32 var_117;
    wp::float32 var_118;
    wp::float32 var_119;
    wp::float32 var_120;
    wp::float32 var_121;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    bool adj_3 = {};
    wp::float32 adj_4 = {};
    wp::int32 adj_5 = {};
    wp::int32 adj_6 = {};
    bool adj_7 = {};
    wp::int32 adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::float32 adj_13 = {};
    wp::int32 adj_14 = {};
    wp::float32 adj_15 = {};
    wp::int32 adj_16 = {};
    wp::float32 adj_17 = {};
    wp::float32 adj_18 = {};
    wp::int32 adj_19 = {};
    wp::float32 adj_20 = {};
    wp::int32 adj_21 = {};
    wp::float32 adj_22 = {};
    wp::float32 adj_23 = {};
    wp::float32 adj_24 = {};
    wp::float32 adj_25 = {};
    wp::float32 adj_26 = {};
    wp::int32 adj_27 = {};
    wp::int32 adj_28 = {};
    bool adj_29 = {};
    wp::int32 adj_30 = {};
    wp::int32 adj_31 = {};
    wp::float32 adj_32 = {};
    wp::int32 adj_33 = {};
    wp::float32 adj_34 = {};
    wp::int32 adj_35 = {};
    wp::float32 adj_36 = {};
    wp::float32 adj_37 = {};
    wp::float32 adj_38 = {};
    bool adj_39 = {};
    wp::float32 adj_40 = {};
    wp::float32 adj_41 = {};
    wp::float32 adj_42 = {};
    wp::int32 adj_43 = {};
    wp::int32 adj_44 = {};
    wp::int32 adj_45 = {};
    wp::int32 adj_46 = {};
    wp::int32 adj_47 = {};
    wp::int32 adj_48 = {};
    wp::array_t<wp::float32> adj_49 = {};
    wp::int32 adj_50 = {};
    wp::int32 adj_51 = {};
    wp::int32 adj_52 = {};
    wp::int32 adj_53 = {};
    wp::float32 adj_54 = {};
    wp::array_t<wp::float32> adj_55 = {};
    wp::float32 adj_56 = {};
    wp::float32 adj_57 = {};
    wp::array_t<wp::float32> adj_58 = {};
    wp::int32 adj_59 = {};
    wp::float32 adj_60 = {};
    wp::array_t<wp::float32> adj_61 = {};
    wp::float32 adj_62 = {};
    wp::float32 adj_63 = {};
    wp::array_t<wp::float32> adj_64 = {};
    wp::int32 adj_65 = {};
    wp::float32 adj_66 = {};
    wp::array_t<wp::float32> adj_67 = {};
    bool adj_68 = {};
    wp::float32 adj_69 = {};
    wp::float32 adj_70 = {};
    wp::array_t<wp::float32> adj_71 = {};
    wp::int32 adj_72 = {};
    wp::float32 adj_73 = {};
    wp::array_t<wp::float32> adj_74 = {};
    wp::float32 adj_75 = {};
    wp::float32 adj_76 = {};
    wp::array_t<wp::float32> adj_77 = {};
    wp::int32 adj_78 = {};
    wp::int32 adj_79 = {};
    wp::int32 adj_80 = {};
    wp::int32 adj_81 = {};
    wp::float32 adj_82 = {};
    wp::array_t<wp::float32> adj_83 = {};
    bool adj_84 = {};
    wp::float32 adj_85 = {};
    wp::array_t<wp::float32> adj_86 = {};
    wp::int32 adj_87 = {};
    wp::int32 adj_88 = {};
    wp::array_t<wp::float32> adj_89 = {};
    wp::int32 adj_90 = {};
    wp::int32 adj_91 = {};
    wp::int32 adj_92 = {};
    wp::array_t<wp::float32> adj_93 = {};
    wp::float32 adj_94 = {};
    wp::array_t<wp::float32> adj_95 = {};
    wp::float32 adj_96 = {};
    wp::float32 adj_97 = {};
    wp::array_t<wp::float32> adj_98 = {};
    wp::float32 adj_99 = {};
    wp::array_t<wp::float32> adj_100 = {};
    wp::float32 adj_101 = {};
    wp::float32 adj_102 = {};
    wp::int32 adj_103 = {};
    wp::int32 adj_104 = {};
    wp::float32 adj_105 = {};
    wp::float32 adj_106 = {};
    wp::int32 adj_107 = {};
    wp::int32 adj_108 = {};
    wp::float32 adj_109 = {};
    wp::float32 adj_110 = {};
    wp::float32 adj_111 = {};
    wp::float32 adj_112 = {};
    wp::float32 adj_113 = {};
    wp::float32 adj_114 = {};
    wp::float32 adj_115 = {};
    wp::float32 adj_116 = {};
    wp::float32 adj_117 = {};
    wp::float32 adj_118 = {};
    wp::float32 adj_119 = {};
    wp::float32 adj_120 = {};
    wp::float32 adj_121 = {};
    //---------
    // forward
    // def optics_response(o: OpticsRec, local: wp.vec3) -> float:                            <L 123>
    // z = local[2]                                                                           <L 125>
    var_1 = wp::extract(var_local, var_0);
    // if z <= 0.0:                                                                           <L 126>
    var_3 = (var_1 <= var_2);
    if (var_3) {
        // return 0.0                                                                         <L 127>
        goto label0;
    }
    // if o.kind == 1:                                                                        <L 128>
    var_5 = &((var_o).kind);
    var_8 = wp::load(var_5);
    var_7 = (var_8 == var_6);
    if (var_7) {
        // return wp.pow(wp.min(z, 1.0), o.exponent)                                          <L 129>
        var_10 = wp::min(var_1, var_9);
        var_11 = &((var_o).exponent);
        var_13 = wp::load(var_11);
        var_12 = wp::pow(var_10, var_13);
        goto label1;
    }
    // s = wp.sqrt(local[0] * local[0] + local[1] * local[1])                                 <L 130>
    var_15 = wp::extract(var_local, var_14);
    var_17 = wp::extract(var_local, var_16);
    var_18 = wp::mul(var_15, var_17);
    var_20 = wp::extract(var_local, var_19);
    var_22 = wp::extract(var_local, var_21);
    var_23 = wp::mul(var_20, var_22);
    var_24 = wp::add(var_18, var_23);
    var_25 = wp::sqrt(var_24);
    // theta = wp.atan2(s, z)  # accurate near the normal, where acos(z) is not               <L 131>
    var_26 = wp::atan2(var_25, var_1);
    // if o.n_phi <= 1:                                                                       <L 132>
    var_27 = &((var_o).n_phi);
    var_30 = wp::load(var_27);
    var_29 = (var_30 <= var_28);
    if (var_29) {
        // return table_column(o, 0, theta)                                                   <L 133>
        var_32 = table_column_0(var_o, var_31, var_26);
        goto label2;
    }
    // phi = wp.atan2(local[1], local[0])                                                     <L 134>
    var_34 = wp::extract(var_local, var_33);
    var_36 = wp::extract(var_local, var_35);
    var_37 = wp::atan2(var_34, var_36);
    // if phi < 0.0:                                                                          <L 135>
    var_39 = (var_37 < var_38);
    if (var_39) {
        // phi = phi + TWO_PI                                                                 <L 136>
        var_41 = wp::add(var_37, var_40);
    }
    var_42 = wp::where(var_39, var_41, var_37);
    // k0 = o.n_phi - 1                                                                       <L 138>
    var_43 = &((var_o).n_phi);
    var_46 = wp::load(var_43);
    var_45 = wp::sub(var_46, var_44);
    // k1 = int(0)                                                                            <L 139>
    var_48 = wp::int(var_47);
    // p0 = o.phi[o.n_phi - 1]                                                                <L 140>
    var_49 = &((var_o).phi);
    var_50 = &((var_o).n_phi);
    var_53 = wp::load(var_50);
    var_52 = wp::sub(var_53, var_51);
    var_55 = wp::load(var_49);
    var_54 = wp::address(var_55, var_52);
    var_57 = wp::load(var_54);
    var_56 = wp::copy(var_57);
    // p1 = o.phi[0] + TWO_PI                                                                 <L 141>
    var_58 = &((var_o).phi);
    var_61 = wp::load(var_58);
    var_60 = wp::address(var_61, var_59);
    var_63 = wp::load(var_60);
    var_62 = wp::add(var_63, var_40);
    // if phi < o.phi[0]:                                                                     <L 142>
    var_64 = &((var_o).phi);
    var_67 = wp::load(var_64);
    var_66 = wp::address(var_67, var_65);
    var_69 = wp::load(var_66);
    var_68 = (var_42 < var_69);
    if (var_68) {
        // p0 = p0 - TWO_PI                                                                   <L 143>
        var_70 = wp::sub(var_56, var_40);
        // p1 = o.phi[0]                                                                      <L 144>
        var_71 = &((var_o).phi);
        var_74 = wp::load(var_71);
        var_73 = wp::address(var_74, var_72);
        var_76 = wp::load(var_73);
        var_75 = wp::copy(var_76);
    }
    if (!var_68) {
        // elif phi < o.phi[o.n_phi - 1]:                                                     <L 145>
        var_77 = &((var_o).phi);
        var_78 = &((var_o).n_phi);
        var_81 = wp::load(var_78);
        var_80 = wp::sub(var_81, var_79);
        var_83 = wp::load(var_77);
        var_82 = wp::address(var_83, var_80);
        var_85 = wp::load(var_82);
        var_84 = (var_42 < var_85);
        if (var_84) {
            // k0 = knot_interval(o.phi, o.n_phi, phi)                                        <L 146>
            var_86 = &((var_o).phi);
            var_87 = &((var_o).n_phi);
            var_89 = wp::load(var_86);
            var_90 = wp::load(var_87);
            var_88 = knot_interval_0(var_89, var_90, var_42);
            // k1 = k0 + 1                                                                    <L 147>
            var_92 = wp::add(var_88, var_91);
            // p0 = o.phi[k0]                                                                 <L 148>
            var_93 = &((var_o).phi);
            var_95 = wp::load(var_93);
            var_94 = wp::address(var_95, var_88);
            var_97 = wp::load(var_94);
            var_96 = wp::copy(var_97);
            // p1 = o.phi[k1]                                                                 <L 149>
            var_98 = &((var_o).phi);
            var_100 = wp::load(var_98);
            var_99 = wp::address(var_100, var_92);
            var_102 = wp::load(var_99);
            var_101 = wp::copy(var_102);
        }
        var_103 = wp::where(var_84, var_88, var_45);
        var_104 = wp::where(var_84, var_92, var_48);
        var_105 = wp::where(var_84, var_96, var_56);
        var_106 = wp::where(var_84, var_101, var_62);
    }
    var_107 = wp::where(var_68, var_45, var_103);
    var_108 = wp::where(var_68, var_48, var_104);
    var_109 = wp::where(var_68, var_70, var_105);
    var_110 = wp::where(var_68, var_75, var_106);
    // f = wp.clamp((phi - p0) / (p1 - p0), 0.0, 1.0)                                         <L 150>
    var_111 = wp::sub(var_42, var_109);
    var_112 = wp::sub(var_110, var_109);
    var_113 = wp::div(var_111, var_112);
    var_116 = wp::clamp(var_113, var_114, var_115);
    // r0 = table_column(o, k0, theta)                                                        <L 151>
    var_117 = table_column_0(var_o, var_107, var_26);
    // r1 = table_column(o, k1, theta)                                                        <L 152>
    var_118 = table_column_0(var_o, var_108, var_26);
    // return r0 + f * (r1 - r0)                                                              <L 153>
    var_119 = wp::sub(var_118, var_117);
    var_120 = wp::mul(var_116, var_119);
    var_121 = wp::add(var_117, var_120);
    goto label3;
    //---------
    // reverse
    label3:;
    adj_121 += adj_ret;
    wp::adj_add(var_117, var_120, adj_117, adj_120, adj_121);
    wp::adj_mul(var_116, var_119, adj_116, adj_119, adj_120);
    wp::adj_sub(var_118, var_117, adj_118, adj_117, adj_119);
    // adj: return r0 + f * (r1 - r0)                                                         <L 153>
    adj_table_column_0(var_o, var_108, var_26, adj_o, adj_108, adj_26, adj_118);
    // adj: r1 = table_column(o, k1, theta)                                                   <L 152>
    adj_table_column_0(var_o, var_107, var_26, adj_o, adj_107, adj_26, adj_117);
    // adj: r0 = table_column(o, k0, theta)                                                   <L 151>
    wp::adj_clamp(var_113, var_114, var_115, adj_113, adj_114, adj_115, adj_116);
    wp::adj_div(var_111, var_112, var_113, adj_111, adj_112, adj_113);
    wp::adj_sub(var_110, var_109, adj_110, adj_109, adj_112);
    wp::adj_sub(var_42, var_109, adj_42, adj_109, adj_111);
    // adj: f = wp.clamp((phi - p0) / (p1 - p0), 0.0, 1.0)                                    <L 150>
    wp::adj_where(var_68, var_75, var_106, adj_68, adj_75, adj_106, adj_110);
    wp::adj_where(var_68, var_70, var_105, adj_68, adj_70, adj_105, adj_109);
    wp::adj_where(var_68, var_48, var_104, adj_68, adj_48, adj_104, adj_108);
    wp::adj_where(var_68, var_45, var_103, adj_68, adj_45, adj_103, adj_107);
    if (!var_68) {
        wp::adj_where(var_84, var_101, var_62, adj_84, adj_101, adj_62, adj_106);
        wp::adj_where(var_84, var_96, var_56, adj_84, adj_96, adj_56, adj_105);
        wp::adj_where(var_84, var_92, var_48, adj_84, adj_92, adj_48, adj_104);
        wp::adj_where(var_84, var_88, var_45, adj_84, adj_88, adj_45, adj_103);
        if (var_84) {
            wp::adj_copy(var_102, adj_99, adj_101);
            wp::adj_address(var_100, var_92, adj_98, adj_92, adj_99);
            adj_o.phi = adj_98;
            // adj: p1 = o.phi[k1]                                                            <L 149>
            wp::adj_copy(var_97, adj_94, adj_96);
            wp::adj_address(var_95, var_88, adj_93, adj_88, adj_94);
            adj_o.phi = adj_93;
            // adj: p0 = o.phi[k0]                                                            <L 148>
            wp::adj_add(var_88, var_91, adj_88, adj_91, adj_92);
            // adj: k1 = k0 + 1                                                               <L 147>
            adj_knot_interval_0(var_89, var_90, var_42, adj_86, adj_87, adj_42, adj_88);
            adj_o.n_phi = adj_87;
            adj_o.phi = adj_86;
            // adj: k0 = knot_interval(o.phi, o.n_phi, phi)                                   <L 146>
        }
        wp::adj_address(var_83, var_80, adj_77, adj_80, adj_82);
        wp::adj_sub(var_81, var_79, adj_78, adj_79, adj_80);
        adj_o.n_phi = adj_78;
        adj_o.phi = adj_77;
        // adj: elif phi < o.phi[o.n_phi - 1]:                                                <L 145>
    }
    if (var_68) {
        wp::adj_copy(var_76, adj_73, adj_75);
        wp::adj_address(var_74, var_72, adj_71, adj_72, adj_73);
        adj_o.phi = adj_71;
        // adj: p1 = o.phi[0]                                                                 <L 144>
        wp::adj_sub(var_56, var_40, adj_56, adj_40, adj_70);
        // adj: p0 = p0 - TWO_PI                                                              <L 143>
    }
    wp::adj_address(var_67, var_65, adj_64, adj_65, adj_66);
    adj_o.phi = adj_64;
    // adj: if phi < o.phi[0]:                                                                <L 142>
    wp::adj_add(var_63, var_40, adj_60, adj_40, adj_62);
    wp::adj_address(var_61, var_59, adj_58, adj_59, adj_60);
    adj_o.phi = adj_58;
    // adj: p1 = o.phi[0] + TWO_PI                                                            <L 141>
    wp::adj_copy(var_57, adj_54, adj_56);
    wp::adj_address(var_55, var_52, adj_49, adj_52, adj_54);
    wp::adj_sub(var_53, var_51, adj_50, adj_51, adj_52);
    adj_o.n_phi = adj_50;
    adj_o.phi = adj_49;
    // adj: p0 = o.phi[o.n_phi - 1]                                                           <L 140>
    // adj: k1 = int(0)                                                                       <L 139>
    wp::adj_sub(var_46, var_44, adj_43, adj_44, adj_45);
    adj_o.n_phi = adj_43;
    // adj: k0 = o.n_phi - 1                                                                  <L 138>
    wp::adj_where(var_39, var_41, var_37, adj_39, adj_41, adj_37, adj_42);
    if (var_39) {
        wp::adj_add(var_37, var_40, adj_37, adj_40, adj_41);
        // adj: phi = phi + TWO_PI                                                            <L 136>
    }
    // adj: if phi < 0.0:                                                                     <L 135>
    wp::adj_atan2(var_34, var_36, adj_34, adj_36, adj_37);
    wp::adj_extract(var_local, var_35, adj_local, adj_35, adj_36);
    wp::adj_extract(var_local, var_33, adj_local, adj_33, adj_34);
    // adj: phi = wp.atan2(local[1], local[0])                                                <L 134>
    if (var_29) {
        label2:;
        adj_32 += adj_ret;
        adj_table_column_0(var_o, var_31, var_26, adj_o, adj_31, adj_26, adj_32);
        // adj: return table_column(o, 0, theta)                                              <L 133>
    }
    adj_o.n_phi = adj_27;
    // adj: if o.n_phi <= 1:                                                                  <L 132>
    wp::adj_atan2(var_25, var_1, adj_25, adj_1, adj_26);
    // adj: theta = wp.atan2(s, z)  # accurate near the normal, where acos(z) is not          <L 131>
    wp::adj_sqrt(var_24, var_25, adj_24, adj_25);
    wp::adj_add(var_18, var_23, adj_18, adj_23, adj_24);
    wp::adj_mul(var_20, var_22, adj_20, adj_22, adj_23);
    wp::adj_extract(var_local, var_21, adj_local, adj_21, adj_22);
    wp::adj_extract(var_local, var_19, adj_local, adj_19, adj_20);
    wp::adj_mul(var_15, var_17, adj_15, adj_17, adj_18);
    wp::adj_extract(var_local, var_16, adj_local, adj_16, adj_17);
    wp::adj_extract(var_local, var_14, adj_local, adj_14, adj_15);
    // adj: s = wp.sqrt(local[0] * local[0] + local[1] * local[1])                            <L 130>
    if (var_7) {
        label1:;
        adj_12 += adj_ret;
        wp::adj_pow(var_10, var_13, var_12, adj_10, adj_11, adj_12);
        adj_o.exponent += adj_11;
        wp::adj_min(var_1, var_9, adj_1, adj_9, adj_10);
        // adj: return wp.pow(wp.min(z, 1.0), o.exponent)                                     <L 129>
    }
    adj_o.kind = adj_5;
    // adj: if o.kind == 1:                                                                   <L 128>
    if (var_3) {
        label0:;
        adj_4 += adj_ret;
        // adj: return 0.0                                                                    <L 127>
    }
    // adj: if z <= 0.0:                                                                      <L 126>
    wp::adj_extract(var_local, var_0, adj_local, adj_0, adj_1);
    // adj: z = local[2]                                                                      <L 125>
    // adj: def optics_response(o: OpticsRec, local: wp.vec3) -> float:                       <L 123>
    return;
}


// /work/main/simulator/kernels/optics.py:156
static void adj_sample_optics_0(
    OpticsRec_3192f450 var_o,
    wp::vec_t<2, wp::float32> var_u,
    OpticsRec_3192f450 & adj_o,
    wp::vec_t<2, wp::float32> & adj_u,
    OpticsSample_915df1ad & adj_ret)
{
    //---------
    // primal vars
    OpticsSample_915df1ad var_0;
    const wp::float32 var_1 = 1.0;
    wp::float32 var_2;
    const wp::float32 var_3 = 6.283185307179586;
    const wp::int32 var_4 = 1;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::int32* var_7;
    const wp::int32 var_8 = 1;
    bool var_9;
    wp::int32 var_10;
    const wp::int32 var_11 = 0;
    wp::float32 var_12;
    const wp::float32 var_13 = 1e-30;
    wp::float32 var_14;
    const wp::float32 var_15 = 1.0;
    wp::float32* var_16;
    const wp::float32 var_17 = 1.0;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::array_t<wp::float32>* var_22;
    wp::array_t<wp::float32>* var_23;
    wp::int32* var_24;
    wp::int32* var_25;
    Dist2DSample_164324b3 var_26;
    wp::array_t<wp::float32> var_27;
    wp::array_t<wp::float32> var_28;
    wp::int32 var_29;
    wp::int32 var_30;
    wp::int32* var_31;
    wp::int32* var_32;
    wp::int32 var_33;
    wp::int32 var_34;
    wp::int32 var_35;
    wp::vec_t<2, wp::float32>* var_36;
    const wp::int32 var_37 = 1;
    wp::float32 var_38;
    wp::vec_t<2, wp::float32> var_39;
    wp::int32* var_40;
    wp::float32 var_41;
    wp::int32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32 var_45;
    const wp::float32 var_46 = 0.0;
    const wp::float32 var_47 = 1.0;
    wp::float32 var_48;
    wp::array_t<wp::float32>* var_49;
    wp::float32* var_50;
    wp::array_t<wp::float32> var_51;
    wp::array_t<wp::float32>* var_52;
    wp::float32* var_53;
    wp::array_t<wp::float32> var_54;
    wp::float32 var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32 var_58;
    wp::vec_t<2, wp::float32>* var_59;
    const wp::int32 var_60 = 0;
    wp::float32 var_61;
    wp::vec_t<2, wp::float32> var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    wp::float32 var_65;
    const wp::float32 var_66 = 0.0;
    const wp::float32 var_67 = 1.0;
    wp::float32 var_68;
    wp::float32 var_69;
    wp::float32 var_70;
    wp::float32 var_71;
    wp::float32 var_72;
    wp::float32 var_73;
    wp::float32 var_74;
    wp::float32 var_75;
    wp::vec_t<3, wp::float32> var_76;
    wp::int32* var_77;
    const wp::int32 var_78 = 1;
    bool var_79;
    wp::int32 var_80;
    wp::vec_t<3, wp::float32>* var_81;
    wp::float32 var_82;
    wp::vec_t<3, wp::float32> var_83;
    wp::float32* var_84;
    wp::int32* var_85;
    wp::float32 var_86;
    wp::int32 var_87;
    wp::array_t<wp::float32>* var_88;
    wp::float32* var_89;
    wp::array_t<wp::float32> var_90;
    wp::float32 var_91;
    wp::float32 var_92;
    wp::float32 var_93;
    wp::float32 var_94;
    wp::float32 var_95;
    const wp::float32 var_96 = 0.0;
    wp::float32* var_97;
    const wp::float32 var_98 = 0.0;
    bool var_99;
    wp::float32 var_100;
    wp::vec_t<3, wp::float32>* var_101;
    wp::float32 var_102;
    wp::vec_t<3, wp::float32> var_103;
    wp::float32* var_104;
    wp::float32 var_105;
    wp::float32 var_106;
    //---------
    // dual vars
    OpticsSample_915df1ad adj_0 = {};
    wp::float32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::int32 adj_4 = {};
    wp::float32 adj_5 = {};
    wp::float32 adj_6 = {};
    wp::int32 adj_7 = {};
    wp::int32 adj_8 = {};
    bool adj_9 = {};
    wp::int32 adj_10 = {};
    wp::int32 adj_11 = {};
    wp::float32 adj_12 = {};
    wp::float32 adj_13 = {};
    wp::float32 adj_14 = {};
    wp::float32 adj_15 = {};
    wp::float32 adj_16 = {};
    wp::float32 adj_17 = {};
    wp::float32 adj_18 = {};
    wp::float32 adj_19 = {};
    wp::float32 adj_20 = {};
    wp::float32 adj_21 = {};
    wp::array_t<wp::float32> adj_22 = {};
    wp::array_t<wp::float32> adj_23 = {};
    wp::int32 adj_24 = {};
    wp::int32 adj_25 = {};
    Dist2DSample_164324b3 adj_26 = {};
    wp::array_t<wp::float32> adj_27 = {};
    wp::array_t<wp::float32> adj_28 = {};
    wp::int32 adj_29 = {};
    wp::int32 adj_30 = {};
    wp::int32 adj_31 = {};
    wp::int32 adj_32 = {};
    wp::int32 adj_33 = {};
    wp::int32 adj_34 = {};
    wp::int32 adj_35 = {};
    wp::vec_t<2, wp::float32> adj_36 = {};
    wp::int32 adj_37 = {};
    wp::float32 adj_38 = {};
    wp::vec_t<2, wp::float32> adj_39 = {};
    wp::int32 adj_40 = {};
    wp::float32 adj_41 = {};
    wp::int32 adj_42 = {};
    wp::float32 adj_43 = {};
    wp::float32 adj_44 = {};
    wp::float32 adj_45 = {};
    wp::float32 adj_46 = {};
    wp::float32 adj_47 = {};
    wp::float32 adj_48 = {};
    wp::array_t<wp::float32> adj_49 = {};
    wp::float32 adj_50 = {};
    wp::array_t<wp::float32> adj_51 = {};
    wp::array_t<wp::float32> adj_52 = {};
    wp::float32 adj_53 = {};
    wp::array_t<wp::float32> adj_54 = {};
    wp::float32 adj_55 = {};
    wp::float32 adj_56 = {};
    wp::float32 adj_57 = {};
    wp::float32 adj_58 = {};
    wp::vec_t<2, wp::float32> adj_59 = {};
    wp::int32 adj_60 = {};
    wp::float32 adj_61 = {};
    wp::vec_t<2, wp::float32> adj_62 = {};
    wp::float32 adj_63 = {};
    wp::float32 adj_64 = {};
    wp::float32 adj_65 = {};
    wp::float32 adj_66 = {};
    wp::float32 adj_67 = {};
    wp::float32 adj_68 = {};
    wp::float32 adj_69 = {};
    wp::float32 adj_70 = {};
    wp::float32 adj_71 = {};
    wp::float32 adj_72 = {};
    wp::float32 adj_73 = {};
    wp::float32 adj_74 = {};
    wp::float32 adj_75 = {};
    wp::vec_t<3, wp::float32> adj_76 = {};
    wp::int32 adj_77 = {};
    wp::int32 adj_78 = {};
    bool adj_79 = {};
    wp::int32 adj_80 = {};
    wp::vec_t<3, wp::float32> adj_81 = {};
    wp::float32 adj_82 = {};
    wp::vec_t<3, wp::float32> adj_83 = {};
    wp::float32 adj_84 = {};
    wp::int32 adj_85 = {};
    wp::float32 adj_86 = {};
    wp::int32 adj_87 = {};
    wp::array_t<wp::float32> adj_88 = {};
    wp::float32 adj_89 = {};
    wp::array_t<wp::float32> adj_90 = {};
    wp::float32 adj_91 = {};
    wp::float32 adj_92 = {};
    wp::float32 adj_93 = {};
    wp::float32 adj_94 = {};
    wp::float32 adj_95 = {};
    wp::float32 adj_96 = {};
    wp::float32 adj_97 = {};
    wp::float32 adj_98 = {};
    bool adj_99 = {};
    wp::float32 adj_100 = {};
    wp::vec_t<3, wp::float32> adj_101 = {};
    wp::float32 adj_102 = {};
    wp::vec_t<3, wp::float32> adj_103 = {};
    wp::float32 adj_104 = {};
    wp::float32 adj_105 = {};
    wp::float32 adj_106 = {};
    //---------
    // forward
    // def sample_optics(o: OpticsRec, u: wp.vec2) -> OpticsSample:                           <L 157>
    // s = OpticsSample()                                                                     <L 160>
    var_0 = OpticsSample_915df1ad();
    // mu = float(1.0)                                                                        <L 161>
    var_2 = wp::float(var_1);
    // phi = TWO_PI * u[1]                                                                    <L 162>
    var_5 = wp::extract(var_u, var_4);
    var_6 = wp::mul(var_3, var_5);
    // if o.kind == 1:                                                                        <L 163>
    var_7 = &((var_o).kind);
    var_10 = wp::load(var_7);
    var_9 = (var_10 == var_8);
    if (var_9) {
        // mu = wp.pow(wp.max(u[0], 1.0e-30), 1.0 / (o.exponent + 1.0))                       <L 164>
        var_12 = wp::extract(var_u, var_11);
        var_14 = wp::max(var_12, var_13);
        var_16 = &((var_o).exponent);
        var_19 = wp::load(var_16);
        var_18 = wp::add(var_19, var_17);
        var_20 = wp::div(var_15, var_18);
        var_21 = wp::pow(var_14, var_20);
    }
    if (!var_9) {
        // ds = sample_piecewise_2d(o.marg, o.cond, o.cols, o.rows, u)  # u[0] the θ bin, u[1] the φ bin       <L 166>
        var_22 = &((var_o).marg);
        var_23 = &((var_o).cond);
        var_24 = &((var_o).cols);
        var_25 = &((var_o).rows);
        var_27 = wp::load(var_22);
        var_28 = wp::load(var_23);
        var_29 = wp::load(var_24);
        var_30 = wp::load(var_25);
        var_26 = sample_piecewise_2d_0(var_27, var_28, var_29, var_30, var_u);
        // j = ds.texel // o.cols                                                             <L 167>
        var_31 = &((var_26).texel);
        var_32 = &((var_o).cols);
        var_34 = wp::load(var_31);
        var_35 = wp::load(var_32);
        var_33 = wp::floordiv(var_34, var_35);
        // fv = wp.clamp(ds.uv[1] * float(o.rows) - float(j), 0.0, 1.0)                       <L 168>
        var_36 = &((var_26).uv);
        var_39 = wp::load(var_36);
        var_38 = wp::extract(var_39, var_37);
        var_40 = &((var_o).rows);
        var_42 = wp::load(var_40);
        var_41 = wp::float(var_42);
        var_43 = wp::mul(var_38, var_41);
        var_44 = wp::float(var_33);
        var_45 = wp::sub(var_43, var_44);
        var_48 = wp::clamp(var_45, var_46, var_47);
        // mu = o.row_mu[j] - fv * o.row_dmu[j]                                               <L 169>
        var_49 = &((var_o).row_mu);
        var_51 = wp::load(var_49);
        var_50 = wp::address(var_51, var_33);
        var_52 = &((var_o).row_dmu);
        var_54 = wp::load(var_52);
        var_53 = wp::address(var_54, var_33);
        var_56 = wp::load(var_53);
        var_55 = wp::mul(var_48, var_56);
        var_58 = wp::load(var_50);
        var_57 = wp::sub(var_58, var_55);
        // phi = TWO_PI * ds.uv[0]                                                            <L 170>
        var_59 = &((var_26).uv);
        var_62 = wp::load(var_59);
        var_61 = wp::extract(var_62, var_60);
        var_63 = wp::mul(var_3, var_61);
    }
    var_64 = wp::where(var_9, var_21, var_57);
    var_65 = wp::where(var_9, var_6, var_63);
    // sin_t = wp.sqrt(wp.max(0.0, 1.0 - mu * mu))                                            <L 171>
    var_68 = wp::mul(var_64, var_64);
    var_69 = wp::sub(var_67, var_68);
    var_70 = wp::max(var_66, var_69);
    var_71 = wp::sqrt(var_70);
    // s.local = wp.vec3(sin_t * wp.cos(phi), sin_t * wp.sin(phi), mu)                        <L 172>
    var_72 = wp::cos(var_65);
    var_73 = wp::mul(var_71, var_72);
    var_74 = wp::sin(var_65);
    var_75 = wp::mul(var_71, var_74);
    var_76 = wp::vec_t<3, wp::float32>(var_73, var_75, var_64);
    var_0.local = var_76;
    // if o.kind == 1:                                                                        <L 173>
    var_77 = &((var_o).kind);
    var_80 = wp::load(var_77);
    var_79 = (var_80 == var_78);
    if (var_79) {
        // s.pdf = pdf_optics(o, s.local)                                                     <L 174>
        var_81 = &((var_0).local);
        var_83 = wp::load(var_81);
        var_82 = pdf_optics_0(var_o, var_83);
        var_0.pdf = var_82;
    }
    if (!var_79) {
        // s.pdf = ds.pdf / (float(o.rows) * o.row_dmu[j] * TWO_PI)                           <L 176>
        var_84 = &((var_26).pdf);
        var_85 = &((var_o).rows);
        var_87 = wp::load(var_85);
        var_86 = wp::float(var_87);
        var_88 = &((var_o).row_dmu);
        var_90 = wp::load(var_88);
        var_89 = wp::address(var_90, var_33);
        var_92 = wp::load(var_89);
        var_91 = wp::mul(var_86, var_92);
        var_93 = wp::mul(var_91, var_3);
        var_95 = wp::load(var_84);
        var_94 = wp::div(var_95, var_93);
        var_0.pdf = var_94;
    }
    // s.weight = 0.0                                                                         <L 177>
    var_0.weight = var_96;
    // if s.pdf > 0.0:                                                                        <L 178>
    var_97 = &((var_0).pdf);
    var_100 = wp::load(var_97);
    var_99 = (var_100 > var_98);
    if (var_99) {
        // s.weight = optics_response(o, s.local) / s.pdf                                     <L 179>
        var_101 = &((var_0).local);
        var_103 = wp::load(var_101);
        var_102 = optics_response_0(var_o, var_103);
        var_104 = &((var_0).pdf);
        var_106 = wp::load(var_104);
        var_105 = wp::div(var_102, var_106);
        var_0.weight = var_105;
    }
    // return s                                                                               <L 180>
    goto label0;
    //---------
    // reverse
    label0:;
    adj_0 += adj_ret;
    // adj: return s                                                                          <L 180>
    if (var_99) {
        adj_105 += adj_0.weight;
        adj_0.weight = {};
        wp::adj_div(var_102, var_106, var_105, adj_102, adj_104, adj_105);
        adj_0.pdf += adj_104;
        adj_optics_response_0(var_o, var_103, adj_o, adj_101, adj_102);
        adj_0.local += adj_101;
        // adj: s.weight = optics_response(o, s.local) / s.pdf                                <L 179>
    }
    adj_0.pdf += adj_97;
    // adj: if s.pdf > 0.0:                                                                   <L 178>
    adj_96 += adj_0.weight;
    adj_0.weight = {};
    // adj: s.weight = 0.0                                                                    <L 177>
    if (!var_79) {
        adj_94 += adj_0.pdf;
        adj_0.pdf = {};
        wp::adj_div(var_95, var_93, var_94, adj_84, adj_93, adj_94);
        wp::adj_mul(var_91, var_3, adj_91, adj_3, adj_93);
        wp::adj_mul(var_86, var_92, adj_86, adj_89, adj_91);
        wp::adj_address(var_90, var_33, adj_88, adj_33, adj_89);
        adj_o.row_dmu = adj_88;
        wp::adj_float(var_87, adj_85, adj_86);
        adj_o.rows = adj_85;
        adj_26.pdf += adj_84;
        // adj: s.pdf = ds.pdf / (float(o.rows) * o.row_dmu[j] * TWO_PI)                      <L 176>
    }
    if (var_79) {
        adj_82 += adj_0.pdf;
        adj_0.pdf = {};
        adj_pdf_optics_0(var_o, var_83, adj_o, adj_81, adj_82);
        adj_0.local += adj_81;
        // adj: s.pdf = pdf_optics(o, s.local)                                                <L 174>
    }
    adj_o.kind = adj_77;
    // adj: if o.kind == 1:                                                                   <L 173>
    adj_76 += adj_0.local;
    adj_0.local = {};
    wp::adj_vec_t(var_73, var_75, var_64, adj_73, adj_75, adj_64, adj_76);
    wp::adj_mul(var_71, var_74, adj_71, adj_74, adj_75);
    wp::adj_sin(var_65, adj_65, adj_74);
    wp::adj_mul(var_71, var_72, adj_71, adj_72, adj_73);
    wp::adj_cos(var_65, adj_65, adj_72);
    // adj: s.local = wp.vec3(sin_t * wp.cos(phi), sin_t * wp.sin(phi), mu)                   <L 172>
    wp::adj_sqrt(var_70, var_71, adj_70, adj_71);
    wp::adj_max(var_66, var_69, adj_66, adj_69, adj_70);
    wp::adj_sub(var_67, var_68, adj_67, adj_68, adj_69);
    wp::adj_mul(var_64, var_64, adj_64, adj_64, adj_68);
    // adj: sin_t = wp.sqrt(wp.max(0.0, 1.0 - mu * mu))                                       <L 171>
    wp::adj_where(var_9, var_6, var_63, adj_9, adj_6, adj_63, adj_65);
    wp::adj_where(var_9, var_21, var_57, adj_9, adj_21, adj_57, adj_64);
    if (!var_9) {
        wp::adj_mul(var_3, var_61, adj_3, adj_61, adj_63);
        wp::adj_extract(var_62, var_60, adj_59, adj_60, adj_61);
        adj_26.uv += adj_59;
        // adj: phi = TWO_PI * ds.uv[0]                                                       <L 170>
        wp::adj_sub(var_58, var_55, adj_50, adj_55, adj_57);
        wp::adj_mul(var_48, var_56, adj_48, adj_53, adj_55);
        wp::adj_address(var_54, var_33, adj_52, adj_33, adj_53);
        adj_o.row_dmu = adj_52;
        wp::adj_address(var_51, var_33, adj_49, adj_33, adj_50);
        adj_o.row_mu = adj_49;
        // adj: mu = o.row_mu[j] - fv * o.row_dmu[j]                                          <L 169>
        wp::adj_clamp(var_45, var_46, var_47, adj_45, adj_46, adj_47, adj_48);
        wp::adj_sub(var_43, var_44, adj_43, adj_44, adj_45);
        wp::adj_float(var_33, adj_33, adj_44);
        wp::adj_mul(var_38, var_41, adj_38, adj_41, adj_43);
        wp::adj_float(var_42, adj_40, adj_41);
        adj_o.rows = adj_40;
        wp::adj_extract(var_39, var_37, adj_36, adj_37, adj_38);
        adj_26.uv += adj_36;
        // adj: fv = wp.clamp(ds.uv[1] * float(o.rows) - float(j), 0.0, 1.0)                  <L 168>
        adj_o.cols = adj_32;
        adj_26.texel = adj_31;
        // adj: j = ds.texel // o.cols                                                        <L 167>
        adj_sample_piecewise_2d_0(var_27, var_28, var_29, var_30, var_u, adj_22, adj_23, adj_24, adj_25, adj_u, adj_26);
        adj_o.rows = adj_25;
        adj_o.cols = adj_24;
        adj_o.cond = adj_23;
        adj_o.marg = adj_22;
        // adj: ds = sample_piecewise_2d(o.marg, o.cond, o.cols, o.rows, u)  # u[0] the θ bin, u[1] the φ bin  <L 166>
    }
    if (var_9) {
        wp::adj_pow(var_14, var_20, var_21, adj_14, adj_20, adj_21);
        wp::adj_div(var_15, var_18, var_20, adj_15, adj_18, adj_20);
        wp::adj_add(var_19, var_17, adj_16, adj_17, adj_18);
        adj_o.exponent += adj_16;
        wp::adj_max(var_12, var_13, adj_12, adj_13, adj_14);
        wp::adj_extract(var_u, var_11, adj_u, adj_11, adj_12);
        // adj: mu = wp.pow(wp.max(u[0], 1.0e-30), 1.0 / (o.exponent + 1.0))                  <L 164>
    }
    adj_o.kind = adj_7;
    // adj: if o.kind == 1:                                                                   <L 163>
    wp::adj_mul(var_3, var_5, adj_3, adj_5, adj_6);
    wp::adj_extract(var_u, var_4, adj_u, adj_4, adj_5);
    // adj: phi = TWO_PI * u[1]                                                               <L 162>
    wp::adj_float(var_1, adj_1, adj_2);
    // adj: mu = float(1.0)                                                                   <L 161>
    // adj: s = OpticsSample()                                                                <L 160>
    // adj: def sample_optics(o: OpticsRec, u: wp.vec2) -> OpticsSample:                      <L 157>
    return;
}

struct wp_args__draw_4263b355 {
    OpticsRec_3192f450 o;
    wp::int32 seed;
    wp::array_t<wp::vec_t<3, wp::float32>> local;
    wp::array_t<wp::float32> pdf;
    wp::array_t<wp::float32> twin;
    wp::array_t<wp::float32> weight;
};


template <bool wp_linear_contiguous>
static void _draw_4263b355_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__draw_4263b355 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__draw_4263b355 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.local.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.weight.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    OpticsRec_3192f450 var_o = _wp_args->o;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> var_local = _wp_args->local;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    wp::array_t<wp::float32> var_twin = _wp_args->twin;
    wp::array_t<wp::float32> var_weight = _wp_args->weight;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    OpticsSample_915df1ad var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::float32* var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    //---------
    // forward
    // def _draw(o: OpticsRec, seed: int, local: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float),       <L 168>
    // i = wp.tid()                                                                           <L 170>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 171>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = sample_optics(o, wp.vec2(wp.randf(rng), wp.randf(rng)))                            <L 172>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_optics_0(var_o, var_4);
    // local[i] = s.local                                                                     <L 173>
    var_6 = &((var_5).local);
    var_8 = wp::load(var_6);
    var_7 = wp::copy(var_8);
    wp::array_store(var_local, var_0, var_7);
    // pdf[i] = s.pdf                                                                         <L 174>
    var_9 = &((var_5).pdf);
    var_11 = wp::load(var_9);
    var_10 = wp::copy(var_11);
    wp::array_store(var_pdf, var_0, var_10);
    // twin[i] = pdf_optics(o, s.local)                                                       <L 175>
    var_12 = &((var_5).local);
    var_14 = wp::load(var_12);
    var_13 = pdf_optics_0(var_o, var_14);
    wp::array_store(var_twin, var_0, var_13);
    // weight[i] = s.weight                                                                   <L 176>
    var_15 = &((var_5).weight);
    var_17 = wp::load(var_15);
    var_16 = wp::copy(var_17);
    wp::array_store(var_weight, var_0, var_16);
}



template <bool wp_linear_contiguous>
static void _draw_4263b355_cpu_kernel_backward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__draw_4263b355 *_wp_args,
    wp_args__draw_4263b355 *_wp_adj_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__draw_4263b355 wp_contiguous_args;
    wp_args__draw_4263b355 wp_contiguous_adj_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_adj_args = *_wp_adj_args;
        wp_contiguous_args.local.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_adj_args.local.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.twin.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.weight.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.weight.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
        _wp_adj_args = &wp_contiguous_adj_args;
    }
    //---------
    // argument vars
    OpticsRec_3192f450 var_o = _wp_args->o;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> var_local = _wp_args->local;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    wp::array_t<wp::float32> var_twin = _wp_args->twin;
    wp::array_t<wp::float32> var_weight = _wp_args->weight;
    OpticsRec_3192f450 adj_o = _wp_adj_args->o;
    wp::int32 adj_seed = _wp_adj_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> adj_local = _wp_adj_args->local;
    wp::array_t<wp::float32> adj_pdf = _wp_adj_args->pdf;
    wp::array_t<wp::float32> adj_twin = _wp_adj_args->twin;
    wp::array_t<wp::float32> adj_weight = _wp_adj_args->weight;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    OpticsSample_915df1ad var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::float32* var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::uint32 adj_1 = {};
    wp::float32 adj_2 = {};
    wp::float32 adj_3 = {};
    wp::vec_t<2, wp::float32> adj_4 = {};
    OpticsSample_915df1ad adj_5 = {};
    wp::vec_t<3, wp::float32> adj_6 = {};
    wp::vec_t<3, wp::float32> adj_7 = {};
    wp::vec_t<3, wp::float32> adj_8 = {};
    wp::float32 adj_9 = {};
    wp::float32 adj_10 = {};
    wp::float32 adj_11 = {};
    wp::vec_t<3, wp::float32> adj_12 = {};
    wp::float32 adj_13 = {};
    wp::vec_t<3, wp::float32> adj_14 = {};
    wp::float32 adj_15 = {};
    wp::float32 adj_16 = {};
    wp::float32 adj_17 = {};
    //---------
    // forward
    // def _draw(o: OpticsRec, seed: int, local: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float),       <L 168>
    // i = wp.tid()                                                                           <L 170>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 171>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = sample_optics(o, wp.vec2(wp.randf(rng), wp.randf(rng)))                            <L 172>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_optics_0(var_o, var_4);
    // local[i] = s.local                                                                     <L 173>
    var_6 = &((var_5).local);
    var_8 = wp::load(var_6);
    var_7 = wp::copy(var_8);
    // wp::array_store(var_local, var_0, var_7);
    // pdf[i] = s.pdf                                                                         <L 174>
    var_9 = &((var_5).pdf);
    var_11 = wp::load(var_9);
    var_10 = wp::copy(var_11);
    // wp::array_store(var_pdf, var_0, var_10);
    // twin[i] = pdf_optics(o, s.local)                                                       <L 175>
    var_12 = &((var_5).local);
    var_14 = wp::load(var_12);
    var_13 = pdf_optics_0(var_o, var_14);
    // wp::array_store(var_twin, var_0, var_13);
    // weight[i] = s.weight                                                                   <L 176>
    var_15 = &((var_5).weight);
    var_17 = wp::load(var_15);
    var_16 = wp::copy(var_17);
    // wp::array_store(var_weight, var_0, var_16);
    //---------
    // reverse
    wp::adj_array_store(var_weight, var_0, var_16, adj_weight, adj_0, adj_16);
    wp::adj_copy(var_17, adj_15, adj_16);
    adj_5.weight += adj_15;
    // adj: weight[i] = s.weight                                                              <L 176>
    wp::adj_array_store(var_twin, var_0, var_13, adj_twin, adj_0, adj_13);
    adj_pdf_optics_0(var_o, var_14, adj_o, adj_12, adj_13);
    adj_5.local += adj_12;
    // adj: twin[i] = pdf_optics(o, s.local)                                                  <L 175>
    wp::adj_array_store(var_pdf, var_0, var_10, adj_pdf, adj_0, adj_10);
    wp::adj_copy(var_11, adj_9, adj_10);
    adj_5.pdf += adj_9;
    // adj: pdf[i] = s.pdf                                                                    <L 174>
    wp::adj_array_store(var_local, var_0, var_7, adj_local, adj_0, adj_7);
    wp::adj_copy(var_8, adj_6, adj_7);
    adj_5.local += adj_6;
    // adj: local[i] = s.local                                                                <L 173>
    adj_sample_optics_0(var_o, var_4, adj_o, adj_4, adj_5);
    wp::adj_vec_t(var_2, var_3, adj_2, adj_3, adj_4);
    // adj: s = sample_optics(o, wp.vec2(wp.randf(rng), wp.randf(rng)))                       <L 172>
    // adj: rng = wp.rand_init(seed, i)                                                       <L 171>
    // adj: i = wp.tid()                                                                      <L 170>
    // adj: def _draw(o: OpticsRec, seed: int, local: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float),  <L 168>
    return;
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _draw_4263b355_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_4263b355 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _draw_4263b355_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void _draw_4263b355_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_4263b355 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->local.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->weight.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        _draw_4263b355_cpu_forward_tasks<true>(dim, _wp_args);
    else
        _draw_4263b355_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void _draw_4263b355_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_4263b355 *_wp_args)
{
    _draw_4263b355_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _draw_4263b355_cpu_backward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_4263b355 *_wp_args,
    wp_args__draw_4263b355 *_wp_adj_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _draw_4263b355_cpu_kernel_backward<wp_linear_contiguous>(
            *dim, task_index, _wp_args, _wp_adj_args);
    }
}

static WP_FORCEINLINE void _draw_4263b355_cpu_backward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_4263b355 *_wp_args,
    wp_args__draw_4263b355 *_wp_adj_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->local.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_adj_args->local.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->twin.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->weight.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->weight.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        _draw_4263b355_cpu_backward_tasks<true>(dim, _wp_args, _wp_adj_args);
    else
        _draw_4263b355_cpu_backward_tasks<false>(dim, _wp_args, _wp_adj_args);
}

extern "C" {

WP_API void _draw_4263b355_cpu_backward(
    wp::launch_bounds_t<1> *dim,
    wp_args__draw_4263b355 *_wp_args,
    wp_args__draw_4263b355 *_wp_adj_args)
{
    _draw_4263b355_cpu_backward_dispatch(dim, _wp_args, _wp_adj_args);
}

} // extern C

struct wp_args__pdf_at_88bd8eff {
    OpticsRec_3192f450 o;
    wp::array_t<wp::vec_t<3, wp::float32>> local;
    wp::array_t<wp::float32> out;
};


template <bool wp_linear_contiguous>
static void _pdf_at_88bd8eff_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__pdf_at_88bd8eff *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__pdf_at_88bd8eff wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.local.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.out.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    OpticsRec_3192f450 var_o = _wp_args->o;
    wp::array_t<wp::vec_t<3, wp::float32>> var_local = _wp_args->local;
    wp::array_t<wp::float32> var_out = _wp_args->out;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::float32 var_2;
    wp::vec_t<3, wp::float32> var_3;
    //---------
    // forward
    // def _pdf_at(o: OpticsRec, local: wp.array(dtype=wp.vec3), out: wp.array(dtype=float)):       <L 180>
    // i = wp.tid()                                                                           <L 181>
    var_0 = builtin_tid1d();
    // out[i] = pdf_optics(o, local[i])                                                       <L 182>
    var_1 = wp::address(var_local, var_0);
    var_3 = wp::load(var_1);
    var_2 = pdf_optics_0(var_o, var_3);
    wp::array_store(var_out, var_0, var_2);
}



template <bool wp_linear_contiguous>
static void _pdf_at_88bd8eff_cpu_kernel_backward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args__pdf_at_88bd8eff *_wp_args,
    wp_args__pdf_at_88bd8eff *_wp_adj_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args__pdf_at_88bd8eff wp_contiguous_args;
    wp_args__pdf_at_88bd8eff wp_contiguous_adj_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_adj_args = *_wp_adj_args;
        wp_contiguous_args.local.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_adj_args.local.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.out.strides[0] = sizeof(wp::float32);
        wp_contiguous_adj_args.out.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
        _wp_adj_args = &wp_contiguous_adj_args;
    }
    //---------
    // argument vars
    OpticsRec_3192f450 var_o = _wp_args->o;
    wp::array_t<wp::vec_t<3, wp::float32>> var_local = _wp_args->local;
    wp::array_t<wp::float32> var_out = _wp_args->out;
    OpticsRec_3192f450 adj_o = _wp_adj_args->o;
    wp::array_t<wp::vec_t<3, wp::float32>> adj_local = _wp_adj_args->local;
    wp::array_t<wp::float32> adj_out = _wp_adj_args->out;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::float32 var_2;
    wp::vec_t<3, wp::float32> var_3;
    //---------
    // dual vars
    wp::int32 adj_0 = {};
    wp::vec_t<3, wp::float32> adj_1 = {};
    wp::float32 adj_2 = {};
    wp::vec_t<3, wp::float32> adj_3 = {};
    //---------
    // forward
    // def _pdf_at(o: OpticsRec, local: wp.array(dtype=wp.vec3), out: wp.array(dtype=float)):       <L 180>
    // i = wp.tid()                                                                           <L 181>
    var_0 = builtin_tid1d();
    // out[i] = pdf_optics(o, local[i])                                                       <L 182>
    var_1 = wp::address(var_local, var_0);
    var_3 = wp::load(var_1);
    var_2 = pdf_optics_0(var_o, var_3);
    // wp::array_store(var_out, var_0, var_2);
    //---------
    // reverse
    wp::adj_array_store(var_out, var_0, var_2, adj_out, adj_0, adj_2);
    adj_pdf_optics_0(var_o, var_3, adj_o, adj_1, adj_2);
    wp::adj_address(var_local, var_0, adj_local, adj_0, adj_1);
    // adj: out[i] = pdf_optics(o, local[i])                                                  <L 182>
    // adj: i = wp.tid()                                                                      <L 181>
    // adj: def _pdf_at(o: OpticsRec, local: wp.array(dtype=wp.vec3), out: wp.array(dtype=float)):  <L 180>
    return;
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _pdf_at_88bd8eff_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__pdf_at_88bd8eff *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _pdf_at_88bd8eff_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void _pdf_at_88bd8eff_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__pdf_at_88bd8eff *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->local.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->out.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        _pdf_at_88bd8eff_cpu_forward_tasks<true>(dim, _wp_args);
    else
        _pdf_at_88bd8eff_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void _pdf_at_88bd8eff_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args__pdf_at_88bd8eff *_wp_args)
{
    _pdf_at_88bd8eff_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void _pdf_at_88bd8eff_cpu_backward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args__pdf_at_88bd8eff *_wp_args,
    wp_args__pdf_at_88bd8eff *_wp_adj_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        _pdf_at_88bd8eff_cpu_kernel_backward<wp_linear_contiguous>(
            *dim, task_index, _wp_args, _wp_adj_args);
    }
}

static WP_FORCEINLINE void _pdf_at_88bd8eff_cpu_backward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args__pdf_at_88bd8eff *_wp_args,
    wp_args__pdf_at_88bd8eff *_wp_adj_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->local.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_adj_args->local.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->out.strides[0] == (int)sizeof(wp::float32)) & (_wp_adj_args->out.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        _pdf_at_88bd8eff_cpu_backward_tasks<true>(dim, _wp_args, _wp_adj_args);
    else
        _pdf_at_88bd8eff_cpu_backward_tasks<false>(dim, _wp_args, _wp_adj_args);
}

extern "C" {

WP_API void _pdf_at_88bd8eff_cpu_backward(
    wp::launch_bounds_t<1> *dim,
    wp_args__pdf_at_88bd8eff *_wp_args,
    wp_args__pdf_at_88bd8eff *_wp_adj_args)
{
    _pdf_at_88bd8eff_cpu_backward_dispatch(dim, _wp_args, _wp_adj_args);
}

} // extern C

