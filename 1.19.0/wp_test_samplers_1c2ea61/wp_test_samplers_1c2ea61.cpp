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


struct LightSample_1981fb4b
{
    wp::vec_t<3, wp::float32> wi;
    wp::float32 dist;
    wp::vec_t<2, wp::float32> value;
    wp::float32 pdf;
    wp::int32 tri;


    LightSample_1981fb4b() = default;
    CUDA_CALLABLE LightSample_1981fb4b(wp::vec_t<3, wp::float32> const& wi,
    wp::float32 const& dist = {},
    wp::vec_t<2, wp::float32> const& value = {},
    wp::float32 const& pdf = {},
    wp::int32 const& tri = {})
        : wi{wi}
        , dist{dist}
        , value{value}
        , pdf{pdf}
        , tri{tri}

    {
    }

    CUDA_CALLABLE LightSample_1981fb4b& operator += (const LightSample_1981fb4b& rhs)
    {    wi += rhs.wi;
    dist += rhs.dist;
    value += rhs.value;
    pdf += rhs.pdf;
    tri += rhs.tri;

        return *this;}

};

static CUDA_CALLABLE void adj_LightSample_1981fb4b(wp::vec_t<3, wp::float32> const&,
    wp::float32 const&,
    wp::vec_t<2, wp::float32> const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_dist,
    wp::vec_t<2, wp::float32> & adj_value,
    wp::float32 & adj_pdf,
    wp::int32 & adj_tri,
    LightSample_1981fb4b & adj_ret)
{
    adj_wi += adj_ret.wi;
    adj_dist += adj_ret.dist;
    adj_value += adj_ret.value;
    adj_pdf += adj_ret.pdf;
    adj_tri += adj_ret.tri;
}

// Required when compiling adjoints.
CUDA_CALLABLE LightSample_1981fb4b add(const LightSample_1981fb4b& a, const LightSample_1981fb4b& b)
{
    return LightSample_1981fb4b();
}

CUDA_CALLABLE void adj_atomic_add(LightSample_1981fb4b* p, LightSample_1981fb4b t)
{
    wp::adj_atomic_add(&p->wi, t.wi);
    wp::adj_atomic_add(&p->dist, t.dist);
    wp::adj_atomic_add(&p->value, t.value);
    wp::adj_atomic_add(&p->pdf, t.pdf);
    wp::adj_atomic_add(&p->tri, t.tri);
}




struct SurfRec_d27fb1d1
{
    wp::float32 coverage;
    wp::int32 pane;
    wp::float32 ior;
    wp::float32 tau;
    wp::int32 glossy;
    wp::float32 roughness;
    wp::float32 metallic;
    wp::float32 specular;
    wp::int32 workflow;
    wp::float32 coat;
    wp::float32 coat_roughness;
    wp::int32 textured;
    wp::float32 threshold;


    SurfRec_d27fb1d1() = default;
    CUDA_CALLABLE SurfRec_d27fb1d1(wp::float32 const& coverage,
    wp::int32 const& pane = {},
    wp::float32 const& ior = {},
    wp::float32 const& tau = {},
    wp::int32 const& glossy = {},
    wp::float32 const& roughness = {},
    wp::float32 const& metallic = {},
    wp::float32 const& specular = {},
    wp::int32 const& workflow = {},
    wp::float32 const& coat = {},
    wp::float32 const& coat_roughness = {},
    wp::int32 const& textured = {},
    wp::float32 const& threshold = {})
        : coverage{coverage}
        , pane{pane}
        , ior{ior}
        , tau{tau}
        , glossy{glossy}
        , roughness{roughness}
        , metallic{metallic}
        , specular{specular}
        , workflow{workflow}
        , coat{coat}
        , coat_roughness{coat_roughness}
        , textured{textured}
        , threshold{threshold}

    {
    }

    CUDA_CALLABLE SurfRec_d27fb1d1& operator += (const SurfRec_d27fb1d1& rhs)
    {    coverage += rhs.coverage;
    pane += rhs.pane;
    ior += rhs.ior;
    tau += rhs.tau;
    glossy += rhs.glossy;
    roughness += rhs.roughness;
    metallic += rhs.metallic;
    specular += rhs.specular;
    workflow += rhs.workflow;
    coat += rhs.coat;
    coat_roughness += rhs.coat_roughness;
    textured += rhs.textured;
    threshold += rhs.threshold;

        return *this;}

};

static CUDA_CALLABLE void adj_SurfRec_d27fb1d1(wp::float32 const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::float32 & adj_coverage,
    wp::int32 & adj_pane,
    wp::float32 & adj_ior,
    wp::float32 & adj_tau,
    wp::int32 & adj_glossy,
    wp::float32 & adj_roughness,
    wp::float32 & adj_metallic,
    wp::float32 & adj_specular,
    wp::int32 & adj_workflow,
    wp::float32 & adj_coat,
    wp::float32 & adj_coat_roughness,
    wp::int32 & adj_textured,
    wp::float32 & adj_threshold,
    SurfRec_d27fb1d1 & adj_ret)
{
    adj_coverage += adj_ret.coverage;
    adj_pane += adj_ret.pane;
    adj_ior += adj_ret.ior;
    adj_tau += adj_ret.tau;
    adj_glossy += adj_ret.glossy;
    adj_roughness += adj_ret.roughness;
    adj_metallic += adj_ret.metallic;
    adj_specular += adj_ret.specular;
    adj_workflow += adj_ret.workflow;
    adj_coat += adj_ret.coat;
    adj_coat_roughness += adj_ret.coat_roughness;
    adj_textured += adj_ret.textured;
    adj_threshold += adj_ret.threshold;
}

// Required when compiling adjoints.
CUDA_CALLABLE SurfRec_d27fb1d1 add(const SurfRec_d27fb1d1& a, const SurfRec_d27fb1d1& b)
{
    return SurfRec_d27fb1d1();
}

CUDA_CALLABLE void adj_atomic_add(SurfRec_d27fb1d1* p, SurfRec_d27fb1d1 t)
{
    wp::adj_atomic_add(&p->coverage, t.coverage);
    wp::adj_atomic_add(&p->pane, t.pane);
    wp::adj_atomic_add(&p->ior, t.ior);
    wp::adj_atomic_add(&p->tau, t.tau);
    wp::adj_atomic_add(&p->glossy, t.glossy);
    wp::adj_atomic_add(&p->roughness, t.roughness);
    wp::adj_atomic_add(&p->metallic, t.metallic);
    wp::adj_atomic_add(&p->specular, t.specular);
    wp::adj_atomic_add(&p->workflow, t.workflow);
    wp::adj_atomic_add(&p->coat, t.coat);
    wp::adj_atomic_add(&p->coat_roughness, t.coat_roughness);
    wp::adj_atomic_add(&p->textured, t.textured);
    wp::adj_atomic_add(&p->threshold, t.threshold);
}




struct GlintRec_cddee017
{
    wp::vec_t<4, wp::float32> plane;
    wp::float32 alpha;
    wp::int32 light;
    wp::vec_t<3, wp::float32> s;


    GlintRec_cddee017() = default;
    CUDA_CALLABLE GlintRec_cddee017(wp::vec_t<4, wp::float32> const& plane,
    wp::float32 const& alpha = {},
    wp::int32 const& light = {},
    wp::vec_t<3, wp::float32> const& s = {})
        : plane{plane}
        , alpha{alpha}
        , light{light}
        , s{s}

    {
    }

    CUDA_CALLABLE GlintRec_cddee017& operator += (const GlintRec_cddee017& rhs)
    {    plane += rhs.plane;
    alpha += rhs.alpha;
    light += rhs.light;
    s += rhs.s;

        return *this;}

};

static CUDA_CALLABLE void adj_GlintRec_cddee017(wp::vec_t<4, wp::float32> const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<4, wp::float32> & adj_plane,
    wp::float32 & adj_alpha,
    wp::int32 & adj_light,
    wp::vec_t<3, wp::float32> & adj_s,
    GlintRec_cddee017 & adj_ret)
{
    adj_plane += adj_ret.plane;
    adj_alpha += adj_ret.alpha;
    adj_light += adj_ret.light;
    adj_s += adj_ret.s;
}

// Required when compiling adjoints.
CUDA_CALLABLE GlintRec_cddee017 add(const GlintRec_cddee017& a, const GlintRec_cddee017& b)
{
    return GlintRec_cddee017();
}

CUDA_CALLABLE void adj_atomic_add(GlintRec_cddee017* p, GlintRec_cddee017 t)
{
    wp::adj_atomic_add(&p->plane, t.plane);
    wp::adj_atomic_add(&p->alpha, t.alpha);
    wp::adj_atomic_add(&p->light, t.light);
    wp::adj_atomic_add(&p->s, t.s);
}




struct TexRec_06276c3b
{
    wp::int32 offset;
    wp::int32 w;
    wp::int32 h;
    wp::int32 wrap_s;
    wp::int32 wrap_t;
    wp::float32 border;


    TexRec_06276c3b() = default;
    CUDA_CALLABLE TexRec_06276c3b(wp::int32 const& offset,
    wp::int32 const& w = {},
    wp::int32 const& h = {},
    wp::int32 const& wrap_s = {},
    wp::int32 const& wrap_t = {},
    wp::float32 const& border = {})
        : offset{offset}
        , w{w}
        , h{h}
        , wrap_s{wrap_s}
        , wrap_t{wrap_t}
        , border{border}

    {
    }

    CUDA_CALLABLE TexRec_06276c3b& operator += (const TexRec_06276c3b& rhs)
    {    offset += rhs.offset;
    w += rhs.w;
    h += rhs.h;
    wrap_s += rhs.wrap_s;
    wrap_t += rhs.wrap_t;
    border += rhs.border;

        return *this;}

};

static CUDA_CALLABLE void adj_TexRec_06276c3b(wp::int32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::int32 & adj_offset,
    wp::int32 & adj_w,
    wp::int32 & adj_h,
    wp::int32 & adj_wrap_s,
    wp::int32 & adj_wrap_t,
    wp::float32 & adj_border,
    TexRec_06276c3b & adj_ret)
{
    adj_offset += adj_ret.offset;
    adj_w += adj_ret.w;
    adj_h += adj_ret.h;
    adj_wrap_s += adj_ret.wrap_s;
    adj_wrap_t += adj_ret.wrap_t;
    adj_border += adj_ret.border;
}

// Required when compiling adjoints.
CUDA_CALLABLE TexRec_06276c3b add(const TexRec_06276c3b& a, const TexRec_06276c3b& b)
{
    return TexRec_06276c3b();
}

CUDA_CALLABLE void adj_atomic_add(TexRec_06276c3b* p, TexRec_06276c3b t)
{
    wp::adj_atomic_add(&p->offset, t.offset);
    wp::adj_atomic_add(&p->w, t.w);
    wp::adj_atomic_add(&p->h, t.h);
    wp::adj_atomic_add(&p->wrap_s, t.wrap_s);
    wp::adj_atomic_add(&p->wrap_t, t.wrap_t);
    wp::adj_atomic_add(&p->border, t.border);
}




struct PortalRec_445c1fd2
{
    wp::vec_t<3, wp::float32> corner;
    wp::vec_t<3, wp::float32> ex;
    wp::vec_t<3, wp::float32> ey;
    wp::vec_t<3, wp::float32> ez;
    wp::float32 width;
    wp::float32 height;


    PortalRec_445c1fd2() = default;
    CUDA_CALLABLE PortalRec_445c1fd2(wp::vec_t<3, wp::float32> const& corner,
    wp::vec_t<3, wp::float32> const& ex = {},
    wp::vec_t<3, wp::float32> const& ey = {},
    wp::vec_t<3, wp::float32> const& ez = {},
    wp::float32 const& width = {},
    wp::float32 const& height = {})
        : corner{corner}
        , ex{ex}
        , ey{ey}
        , ez{ez}
        , width{width}
        , height{height}

    {
    }

    CUDA_CALLABLE PortalRec_445c1fd2& operator += (const PortalRec_445c1fd2& rhs)
    {    corner += rhs.corner;
    ex += rhs.ex;
    ey += rhs.ey;
    ez += rhs.ez;
    width += rhs.width;
    height += rhs.height;

        return *this;}

};

static CUDA_CALLABLE void adj_PortalRec_445c1fd2(wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::vec_t<3, wp::float32> & adj_corner,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::vec_t<3, wp::float32> & adj_ez,
    wp::float32 & adj_width,
    wp::float32 & adj_height,
    PortalRec_445c1fd2 & adj_ret)
{
    adj_corner += adj_ret.corner;
    adj_ex += adj_ret.ex;
    adj_ey += adj_ret.ey;
    adj_ez += adj_ret.ez;
    adj_width += adj_ret.width;
    adj_height += adj_ret.height;
}

// Required when compiling adjoints.
CUDA_CALLABLE PortalRec_445c1fd2 add(const PortalRec_445c1fd2& a, const PortalRec_445c1fd2& b)
{
    return PortalRec_445c1fd2();
}

CUDA_CALLABLE void adj_atomic_add(PortalRec_445c1fd2* p, PortalRec_445c1fd2 t)
{
    wp::adj_atomic_add(&p->corner, t.corner);
    wp::adj_atomic_add(&p->ex, t.ex);
    wp::adj_atomic_add(&p->ey, t.ey);
    wp::adj_atomic_add(&p->ez, t.ez);
    wp::adj_atomic_add(&p->width, t.width);
    wp::adj_atomic_add(&p->height, t.height);
}




struct LightRec_73c30c8a
{
    wp::int32 kind;
    wp::vec_t<3, wp::float32> position;
    wp::vec_t<3, wp::float32> ex;
    wp::vec_t<3, wp::float32> ey;
    wp::vec_t<3, wp::float32> ez;
    wp::vec_t<2, wp::float32> emission;
    wp::float32 width;
    wp::float32 height;
    wp::float32 radius;
    wp::float32 one_minus_cos;
    wp::float32 area;
    wp::float32 length;
    wp::int32 has_map;
    wp::int32 map_w;
    wp::int32 map_h;
    wp::array_t<wp::float32> map;
    wp::array_t<wp::float32> map_marg;
    wp::array_t<wp::float32> map_cond;
    wp::int32 shaped;
    wp::vec_t<4, wp::float32> shaping;
    wp::float32 ies_scale;
    wp::int32 n_portals;
    wp::array_t<PortalRec_445c1fd2> portals;


    LightRec_73c30c8a() = default;
    CUDA_CALLABLE LightRec_73c30c8a(wp::int32 const& kind,
    wp::vec_t<3, wp::float32> const& position = {},
    wp::vec_t<3, wp::float32> const& ex = {},
    wp::vec_t<3, wp::float32> const& ey = {},
    wp::vec_t<3, wp::float32> const& ez = {},
    wp::vec_t<2, wp::float32> const& emission = {},
    wp::float32 const& width = {},
    wp::float32 const& height = {},
    wp::float32 const& radius = {},
    wp::float32 const& one_minus_cos = {},
    wp::float32 const& area = {},
    wp::float32 const& length = {},
    wp::int32 const& has_map = {},
    wp::int32 const& map_w = {},
    wp::int32 const& map_h = {},
    wp::array_t<wp::float32> const& map = {},
    wp::array_t<wp::float32> const& map_marg = {},
    wp::array_t<wp::float32> const& map_cond = {},
    wp::int32 const& shaped = {},
    wp::vec_t<4, wp::float32> const& shaping = {},
    wp::float32 const& ies_scale = {},
    wp::int32 const& n_portals = {},
    wp::array_t<PortalRec_445c1fd2> const& portals = {})
        : kind{kind}
        , position{position}
        , ex{ex}
        , ey{ey}
        , ez{ez}
        , emission{emission}
        , width{width}
        , height{height}
        , radius{radius}
        , one_minus_cos{one_minus_cos}
        , area{area}
        , length{length}
        , has_map{has_map}
        , map_w{map_w}
        , map_h{map_h}
        , map{map}
        , map_marg{map_marg}
        , map_cond{map_cond}
        , shaped{shaped}
        , shaping{shaping}
        , ies_scale{ies_scale}
        , n_portals{n_portals}
        , portals{portals}

    {
    }

    CUDA_CALLABLE LightRec_73c30c8a& operator += (const LightRec_73c30c8a& rhs)
    {    kind += rhs.kind;
    position += rhs.position;
    ex += rhs.ex;
    ey += rhs.ey;
    ez += rhs.ez;
    emission += rhs.emission;
    width += rhs.width;
    height += rhs.height;
    radius += rhs.radius;
    one_minus_cos += rhs.one_minus_cos;
    area += rhs.area;
    length += rhs.length;
    has_map += rhs.has_map;
    map_w += rhs.map_w;
    map_h += rhs.map_h;
    shaped += rhs.shaped;
    shaping += rhs.shaping;
    ies_scale += rhs.ies_scale;
    n_portals += rhs.n_portals;

        return *this;}

};

static CUDA_CALLABLE void adj_LightRec_73c30c8a(wp::int32 const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<2, wp::float32> const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::int32 const&,
    wp::vec_t<4, wp::float32> const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::array_t<PortalRec_445c1fd2> const&,
    wp::int32 & adj_kind,
    wp::vec_t<3, wp::float32> & adj_position,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::vec_t<3, wp::float32> & adj_ez,
    wp::vec_t<2, wp::float32> & adj_emission,
    wp::float32 & adj_width,
    wp::float32 & adj_height,
    wp::float32 & adj_radius,
    wp::float32 & adj_one_minus_cos,
    wp::float32 & adj_area,
    wp::float32 & adj_length,
    wp::int32 & adj_has_map,
    wp::int32 & adj_map_w,
    wp::int32 & adj_map_h,
    wp::array_t<wp::float32> & adj_map,
    wp::array_t<wp::float32> & adj_map_marg,
    wp::array_t<wp::float32> & adj_map_cond,
    wp::int32 & adj_shaped,
    wp::vec_t<4, wp::float32> & adj_shaping,
    wp::float32 & adj_ies_scale,
    wp::int32 & adj_n_portals,
    wp::array_t<PortalRec_445c1fd2> & adj_portals,
    LightRec_73c30c8a & adj_ret)
{
    adj_kind += adj_ret.kind;
    adj_position += adj_ret.position;
    adj_ex += adj_ret.ex;
    adj_ey += adj_ret.ey;
    adj_ez += adj_ret.ez;
    adj_emission += adj_ret.emission;
    adj_width += adj_ret.width;
    adj_height += adj_ret.height;
    adj_radius += adj_ret.radius;
    adj_one_minus_cos += adj_ret.one_minus_cos;
    adj_area += adj_ret.area;
    adj_length += adj_ret.length;
    adj_has_map += adj_ret.has_map;
    adj_map_w += adj_ret.map_w;
    adj_map_h += adj_ret.map_h;
    adj_map = adj_ret.map;
    adj_map_marg = adj_ret.map_marg;
    adj_map_cond = adj_ret.map_cond;
    adj_shaped += adj_ret.shaped;
    adj_shaping += adj_ret.shaping;
    adj_ies_scale += adj_ret.ies_scale;
    adj_n_portals += adj_ret.n_portals;
    adj_portals = adj_ret.portals;
}

// Required when compiling adjoints.
CUDA_CALLABLE LightRec_73c30c8a add(const LightRec_73c30c8a& a, const LightRec_73c30c8a& b)
{
    return LightRec_73c30c8a();
}

CUDA_CALLABLE void adj_atomic_add(LightRec_73c30c8a* p, LightRec_73c30c8a t)
{
    wp::adj_atomic_add(&p->kind, t.kind);
    wp::adj_atomic_add(&p->position, t.position);
    wp::adj_atomic_add(&p->ex, t.ex);
    wp::adj_atomic_add(&p->ey, t.ey);
    wp::adj_atomic_add(&p->ez, t.ez);
    wp::adj_atomic_add(&p->emission, t.emission);
    wp::adj_atomic_add(&p->width, t.width);
    wp::adj_atomic_add(&p->height, t.height);
    wp::adj_atomic_add(&p->radius, t.radius);
    wp::adj_atomic_add(&p->one_minus_cos, t.one_minus_cos);
    wp::adj_atomic_add(&p->area, t.area);
    wp::adj_atomic_add(&p->length, t.length);
    wp::adj_atomic_add(&p->has_map, t.has_map);
    wp::adj_atomic_add(&p->map_w, t.map_w);
    wp::adj_atomic_add(&p->map_h, t.map_h);
    wp::adj_atomic_add(&p->map, t.map);
    wp::adj_atomic_add(&p->map_marg, t.map_marg);
    wp::adj_atomic_add(&p->map_cond, t.map_cond);
    wp::adj_atomic_add(&p->shaped, t.shaped);
    wp::adj_atomic_add(&p->shaping, t.shaping);
    wp::adj_atomic_add(&p->ies_scale, t.ies_scale);
    wp::adj_atomic_add(&p->n_portals, t.n_portals);
    wp::adj_atomic_add(&p->portals, t.portals);
}




struct GuideRec_b7ff9d66
{
    wp::array_t<wp::int32> tri_m;
    wp::array_t<wp::int32> tri_offset;
    wp::array_t<wp::int32> patch_tri;
    wp::array_t<wp::int32> tri_row;
    wp::int32 n_rows;
    wp::array_t<wp::float32> density;
    wp::array_t<wp::int32> ids;
    wp::array_t<wp::float32> cdf;
    wp::array_t<wp::int32> row_start;
    wp::int32 n;
    wp::int32 n_patches;
    wp::array_t<wp::vec_t<2, wp::float32>> tally;


    GuideRec_b7ff9d66() = default;
    CUDA_CALLABLE GuideRec_b7ff9d66(wp::array_t<wp::int32> const& tri_m,
    wp::array_t<wp::int32> const& tri_offset = {},
    wp::array_t<wp::int32> const& patch_tri = {},
    wp::array_t<wp::int32> const& tri_row = {},
    wp::int32 const& n_rows = {},
    wp::array_t<wp::float32> const& density = {},
    wp::array_t<wp::int32> const& ids = {},
    wp::array_t<wp::float32> const& cdf = {},
    wp::array_t<wp::int32> const& row_start = {},
    wp::int32 const& n = {},
    wp::int32 const& n_patches = {},
    wp::array_t<wp::vec_t<2, wp::float32>> const& tally = {})
        : tri_m{tri_m}
        , tri_offset{tri_offset}
        , patch_tri{patch_tri}
        , tri_row{tri_row}
        , n_rows{n_rows}
        , density{density}
        , ids{ids}
        , cdf{cdf}
        , row_start{row_start}
        , n{n}
        , n_patches{n_patches}
        , tally{tally}

    {
    }

    CUDA_CALLABLE GuideRec_b7ff9d66& operator += (const GuideRec_b7ff9d66& rhs)
    {    n_rows += rhs.n_rows;
    n += rhs.n;
    n_patches += rhs.n_patches;

        return *this;}

};

static CUDA_CALLABLE void adj_GuideRec_b7ff9d66(wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::int32 const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::int32> const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::array_t<wp::vec_t<2, wp::float32>> const&,
    wp::array_t<wp::int32> & adj_tri_m,
    wp::array_t<wp::int32> & adj_tri_offset,
    wp::array_t<wp::int32> & adj_patch_tri,
    wp::array_t<wp::int32> & adj_tri_row,
    wp::int32 & adj_n_rows,
    wp::array_t<wp::float32> & adj_density,
    wp::array_t<wp::int32> & adj_ids,
    wp::array_t<wp::float32> & adj_cdf,
    wp::array_t<wp::int32> & adj_row_start,
    wp::int32 & adj_n,
    wp::int32 & adj_n_patches,
    wp::array_t<wp::vec_t<2, wp::float32>> & adj_tally,
    GuideRec_b7ff9d66 & adj_ret)
{
    adj_tri_m = adj_ret.tri_m;
    adj_tri_offset = adj_ret.tri_offset;
    adj_patch_tri = adj_ret.patch_tri;
    adj_tri_row = adj_ret.tri_row;
    adj_n_rows += adj_ret.n_rows;
    adj_density = adj_ret.density;
    adj_ids = adj_ret.ids;
    adj_cdf = adj_ret.cdf;
    adj_row_start = adj_ret.row_start;
    adj_n += adj_ret.n;
    adj_n_patches += adj_ret.n_patches;
    adj_tally = adj_ret.tally;
}

// Required when compiling adjoints.
CUDA_CALLABLE GuideRec_b7ff9d66 add(const GuideRec_b7ff9d66& a, const GuideRec_b7ff9d66& b)
{
    return GuideRec_b7ff9d66();
}

CUDA_CALLABLE void adj_atomic_add(GuideRec_b7ff9d66* p, GuideRec_b7ff9d66 t)
{
    wp::adj_atomic_add(&p->tri_m, t.tri_m);
    wp::adj_atomic_add(&p->tri_offset, t.tri_offset);
    wp::adj_atomic_add(&p->patch_tri, t.patch_tri);
    wp::adj_atomic_add(&p->tri_row, t.tri_row);
    wp::adj_atomic_add(&p->n_rows, t.n_rows);
    wp::adj_atomic_add(&p->density, t.density);
    wp::adj_atomic_add(&p->ids, t.ids);
    wp::adj_atomic_add(&p->cdf, t.cdf);
    wp::adj_atomic_add(&p->row_start, t.row_start);
    wp::adj_atomic_add(&p->n, t.n);
    wp::adj_atomic_add(&p->n_patches, t.n_patches);
    wp::adj_atomic_add(&p->tally, t.tally);
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




struct SceneRec_19d73428
{
    wp::uint64 mesh;
    wp::int32 has_mesh;
    wp::array_t<wp::vec_t<3, wp::float32>> points;
    wp::array_t<wp::int32> tris;
    wp::array_t<wp::float32> albedo;
    wp::array_t<wp::vec_t<2, wp::float32>> emission;
    wp::array_t<wp::int32> two_sided;
    wp::int32 surfaces;
    wp::array_t<wp::int32> surf_id;
    wp::array_t<wp::int32> surf_side;
    wp::array_t<SurfRec_d27fb1d1> surf;
    wp::int32 n_glints;
    wp::array_t<GlintRec_cddee017> glints;
    wp::array_t<wp::int32> tex_id;
    wp::array_t<wp::vec_t<2, wp::float32>> tex_uv;
    wp::array_t<TexRec_06276c3b> tex;
    wp::array_t<wp::float32> texels;
    wp::int32 n_mirror_planes;
    wp::array_t<wp::vec_t<4, wp::float32>> mirror_planes;
    wp::array_t<wp::int32> face_mirror;
    wp::array_t<wp::int32> plane_mirror;
    wp::int32 n_shaded;
    wp::array_t<wp::int32> shade_id;
    wp::array_t<wp::vec_t<3, wp::float32>> shade_n;
    wp::int32 n_curves;
    wp::array_t<wp::int32> face_curve;
    wp::array_t<wp::vec_t<4, wp::float32>> curve_sphere;
    wp::array_t<wp::int32> emit_tris;
    wp::array_t<wp::float32> emit_cdf;
    wp::array_t<wp::float32> emit_prob;
    wp::int32 n_pieces;
    wp::array_t<wp::int32> emit_piece;
    wp::array_t<wp::int32> piece_first;
    wp::array_t<wp::int32> piece_count;
    wp::array_t<wp::vec_t<3, wp::float32>> piece_centre;
    wp::array_t<wp::vec_t<3, wp::float32>> piece_normal;
    wp::array_t<wp::vec_t<4, wp::float32>> piece_shape;
    wp::array_t<wp::float32> piece_factor;
    wp::array_t<wp::float32> piece_power;
    wp::array_t<wp::vec_t<4, wp::float32>> piece_tally;
    wp::array_t<LightRec_73c30c8a> lights;
    wp::int32 n_lights;
    wp::float32 eps;
    wp::array_t<wp::int32> ray_counts;
    wp::array_t<wp::int32> light_mask;
    wp::array_t<wp::float32> spectral_reflectance;
    wp::array_t<wp::int32> spectral_face;
    wp::array_t<wp::float32> spectral_emission;
    wp::array_t<wp::int32> spectral_face_emission;
    wp::array_t<wp::float32> response_weights;
    wp::array_t<wp::vec_t<4, wp::float32>> response_lanes;
    wp::array_t<wp::float32> colour_weights;
    wp::array_t<wp::vec_t<3, wp::int32>> spectral_surface;
    wp::int32 spectral_panes;
    wp::array_t<wp::int32> light_group;
    wp::array_t<wp::int32> patch_base;
    GuideRec_b7ff9d66 guide;
    wp::array_t<wp::float32> pick_factor;
    wp::array_t<wp::vec_t<2, wp::float32>> pick_tally;
    wp::int32 n_patch_pick;
    wp::array_t<wp::float32> patch_pick_factor;
    wp::array_t<wp::vec_t<3, wp::float32>> patch_pick_tally;
    wp::array_t<OpticsRec_3192f450> optics;


    SceneRec_19d73428() = default;
    CUDA_CALLABLE SceneRec_19d73428(wp::uint64 const& mesh,
    wp::int32 const& has_mesh = {},
    wp::array_t<wp::vec_t<3, wp::float32>> const& points = {},
    wp::array_t<wp::int32> const& tris = {},
    wp::array_t<wp::float32> const& albedo = {},
    wp::array_t<wp::vec_t<2, wp::float32>> const& emission = {},
    wp::array_t<wp::int32> const& two_sided = {},
    wp::int32 const& surfaces = {},
    wp::array_t<wp::int32> const& surf_id = {},
    wp::array_t<wp::int32> const& surf_side = {},
    wp::array_t<SurfRec_d27fb1d1> const& surf = {},
    wp::int32 const& n_glints = {},
    wp::array_t<GlintRec_cddee017> const& glints = {},
    wp::array_t<wp::int32> const& tex_id = {},
    wp::array_t<wp::vec_t<2, wp::float32>> const& tex_uv = {},
    wp::array_t<TexRec_06276c3b> const& tex = {},
    wp::array_t<wp::float32> const& texels = {},
    wp::int32 const& n_mirror_planes = {},
    wp::array_t<wp::vec_t<4, wp::float32>> const& mirror_planes = {},
    wp::array_t<wp::int32> const& face_mirror = {},
    wp::array_t<wp::int32> const& plane_mirror = {},
    wp::int32 const& n_shaded = {},
    wp::array_t<wp::int32> const& shade_id = {},
    wp::array_t<wp::vec_t<3, wp::float32>> const& shade_n = {},
    wp::int32 const& n_curves = {},
    wp::array_t<wp::int32> const& face_curve = {},
    wp::array_t<wp::vec_t<4, wp::float32>> const& curve_sphere = {},
    wp::array_t<wp::int32> const& emit_tris = {},
    wp::array_t<wp::float32> const& emit_cdf = {},
    wp::array_t<wp::float32> const& emit_prob = {},
    wp::int32 const& n_pieces = {},
    wp::array_t<wp::int32> const& emit_piece = {},
    wp::array_t<wp::int32> const& piece_first = {},
    wp::array_t<wp::int32> const& piece_count = {},
    wp::array_t<wp::vec_t<3, wp::float32>> const& piece_centre = {},
    wp::array_t<wp::vec_t<3, wp::float32>> const& piece_normal = {},
    wp::array_t<wp::vec_t<4, wp::float32>> const& piece_shape = {},
    wp::array_t<wp::float32> const& piece_factor = {},
    wp::array_t<wp::float32> const& piece_power = {},
    wp::array_t<wp::vec_t<4, wp::float32>> const& piece_tally = {},
    wp::array_t<LightRec_73c30c8a> const& lights = {},
    wp::int32 const& n_lights = {},
    wp::float32 const& eps = {},
    wp::array_t<wp::int32> const& ray_counts = {},
    wp::array_t<wp::int32> const& light_mask = {},
    wp::array_t<wp::float32> const& spectral_reflectance = {},
    wp::array_t<wp::int32> const& spectral_face = {},
    wp::array_t<wp::float32> const& spectral_emission = {},
    wp::array_t<wp::int32> const& spectral_face_emission = {},
    wp::array_t<wp::float32> const& response_weights = {},
    wp::array_t<wp::vec_t<4, wp::float32>> const& response_lanes = {},
    wp::array_t<wp::float32> const& colour_weights = {},
    wp::array_t<wp::vec_t<3, wp::int32>> const& spectral_surface = {},
    wp::int32 const& spectral_panes = {},
    wp::array_t<wp::int32> const& light_group = {},
    wp::array_t<wp::int32> const& patch_base = {},
    GuideRec_b7ff9d66 const& guide = {},
    wp::array_t<wp::float32> const& pick_factor = {},
    wp::array_t<wp::vec_t<2, wp::float32>> const& pick_tally = {},
    wp::int32 const& n_patch_pick = {},
    wp::array_t<wp::float32> const& patch_pick_factor = {},
    wp::array_t<wp::vec_t<3, wp::float32>> const& patch_pick_tally = {},
    wp::array_t<OpticsRec_3192f450> const& optics = {})
        : mesh{mesh}
        , has_mesh{has_mesh}
        , points{points}
        , tris{tris}
        , albedo{albedo}
        , emission{emission}
        , two_sided{two_sided}
        , surfaces{surfaces}
        , surf_id{surf_id}
        , surf_side{surf_side}
        , surf{surf}
        , n_glints{n_glints}
        , glints{glints}
        , tex_id{tex_id}
        , tex_uv{tex_uv}
        , tex{tex}
        , texels{texels}
        , n_mirror_planes{n_mirror_planes}
        , mirror_planes{mirror_planes}
        , face_mirror{face_mirror}
        , plane_mirror{plane_mirror}
        , n_shaded{n_shaded}
        , shade_id{shade_id}
        , shade_n{shade_n}
        , n_curves{n_curves}
        , face_curve{face_curve}
        , curve_sphere{curve_sphere}
        , emit_tris{emit_tris}
        , emit_cdf{emit_cdf}
        , emit_prob{emit_prob}
        , n_pieces{n_pieces}
        , emit_piece{emit_piece}
        , piece_first{piece_first}
        , piece_count{piece_count}
        , piece_centre{piece_centre}
        , piece_normal{piece_normal}
        , piece_shape{piece_shape}
        , piece_factor{piece_factor}
        , piece_power{piece_power}
        , piece_tally{piece_tally}
        , lights{lights}
        , n_lights{n_lights}
        , eps{eps}
        , ray_counts{ray_counts}
        , light_mask{light_mask}
        , spectral_reflectance{spectral_reflectance}
        , spectral_face{spectral_face}
        , spectral_emission{spectral_emission}
        , spectral_face_emission{spectral_face_emission}
        , response_weights{response_weights}
        , response_lanes{response_lanes}
        , colour_weights{colour_weights}
        , spectral_surface{spectral_surface}
        , spectral_panes{spectral_panes}
        , light_group{light_group}
        , patch_base{patch_base}
        , guide{guide}
        , pick_factor{pick_factor}
        , pick_tally{pick_tally}
        , n_patch_pick{n_patch_pick}
        , patch_pick_factor{patch_pick_factor}
        , patch_pick_tally{patch_pick_tally}
        , optics{optics}

    {
    }

    CUDA_CALLABLE SceneRec_19d73428& operator += (const SceneRec_19d73428& rhs)
    {    mesh += rhs.mesh;
    has_mesh += rhs.has_mesh;
    surfaces += rhs.surfaces;
    n_glints += rhs.n_glints;
    n_mirror_planes += rhs.n_mirror_planes;
    n_shaded += rhs.n_shaded;
    n_curves += rhs.n_curves;
    n_pieces += rhs.n_pieces;
    n_lights += rhs.n_lights;
    eps += rhs.eps;
    spectral_panes += rhs.spectral_panes;
    guide += rhs.guide;
    n_patch_pick += rhs.n_patch_pick;

        return *this;}

};

static CUDA_CALLABLE void adj_SceneRec_19d73428(wp::uint64 const&,
    wp::int32 const&,
    wp::array_t<wp::vec_t<3, wp::float32>> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::vec_t<2, wp::float32>> const&,
    wp::array_t<wp::int32> const&,
    wp::int32 const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<SurfRec_d27fb1d1> const&,
    wp::int32 const&,
    wp::array_t<GlintRec_cddee017> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::vec_t<2, wp::float32>> const&,
    wp::array_t<TexRec_06276c3b> const&,
    wp::array_t<wp::float32> const&,
    wp::int32 const&,
    wp::array_t<wp::vec_t<4, wp::float32>> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::int32 const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::vec_t<3, wp::float32>> const&,
    wp::int32 const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::vec_t<4, wp::float32>> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::int32 const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::vec_t<3, wp::float32>> const&,
    wp::array_t<wp::vec_t<3, wp::float32>> const&,
    wp::array_t<wp::vec_t<4, wp::float32>> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::vec_t<4, wp::float32>> const&,
    wp::array_t<LightRec_73c30c8a> const&,
    wp::int32 const&,
    wp::float32 const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::vec_t<4, wp::float32>> const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::vec_t<3, wp::int32>> const&,
    wp::int32 const&,
    wp::array_t<wp::int32> const&,
    wp::array_t<wp::int32> const&,
    GuideRec_b7ff9d66 const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::vec_t<2, wp::float32>> const&,
    wp::int32 const&,
    wp::array_t<wp::float32> const&,
    wp::array_t<wp::vec_t<3, wp::float32>> const&,
    wp::array_t<OpticsRec_3192f450> const&,
    wp::uint64 & adj_mesh,
    wp::int32 & adj_has_mesh,
    wp::array_t<wp::vec_t<3, wp::float32>> & adj_points,
    wp::array_t<wp::int32> & adj_tris,
    wp::array_t<wp::float32> & adj_albedo,
    wp::array_t<wp::vec_t<2, wp::float32>> & adj_emission,
    wp::array_t<wp::int32> & adj_two_sided,
    wp::int32 & adj_surfaces,
    wp::array_t<wp::int32> & adj_surf_id,
    wp::array_t<wp::int32> & adj_surf_side,
    wp::array_t<SurfRec_d27fb1d1> & adj_surf,
    wp::int32 & adj_n_glints,
    wp::array_t<GlintRec_cddee017> & adj_glints,
    wp::array_t<wp::int32> & adj_tex_id,
    wp::array_t<wp::vec_t<2, wp::float32>> & adj_tex_uv,
    wp::array_t<TexRec_06276c3b> & adj_tex,
    wp::array_t<wp::float32> & adj_texels,
    wp::int32 & adj_n_mirror_planes,
    wp::array_t<wp::vec_t<4, wp::float32>> & adj_mirror_planes,
    wp::array_t<wp::int32> & adj_face_mirror,
    wp::array_t<wp::int32> & adj_plane_mirror,
    wp::int32 & adj_n_shaded,
    wp::array_t<wp::int32> & adj_shade_id,
    wp::array_t<wp::vec_t<3, wp::float32>> & adj_shade_n,
    wp::int32 & adj_n_curves,
    wp::array_t<wp::int32> & adj_face_curve,
    wp::array_t<wp::vec_t<4, wp::float32>> & adj_curve_sphere,
    wp::array_t<wp::int32> & adj_emit_tris,
    wp::array_t<wp::float32> & adj_emit_cdf,
    wp::array_t<wp::float32> & adj_emit_prob,
    wp::int32 & adj_n_pieces,
    wp::array_t<wp::int32> & adj_emit_piece,
    wp::array_t<wp::int32> & adj_piece_first,
    wp::array_t<wp::int32> & adj_piece_count,
    wp::array_t<wp::vec_t<3, wp::float32>> & adj_piece_centre,
    wp::array_t<wp::vec_t<3, wp::float32>> & adj_piece_normal,
    wp::array_t<wp::vec_t<4, wp::float32>> & adj_piece_shape,
    wp::array_t<wp::float32> & adj_piece_factor,
    wp::array_t<wp::float32> & adj_piece_power,
    wp::array_t<wp::vec_t<4, wp::float32>> & adj_piece_tally,
    wp::array_t<LightRec_73c30c8a> & adj_lights,
    wp::int32 & adj_n_lights,
    wp::float32 & adj_eps,
    wp::array_t<wp::int32> & adj_ray_counts,
    wp::array_t<wp::int32> & adj_light_mask,
    wp::array_t<wp::float32> & adj_spectral_reflectance,
    wp::array_t<wp::int32> & adj_spectral_face,
    wp::array_t<wp::float32> & adj_spectral_emission,
    wp::array_t<wp::int32> & adj_spectral_face_emission,
    wp::array_t<wp::float32> & adj_response_weights,
    wp::array_t<wp::vec_t<4, wp::float32>> & adj_response_lanes,
    wp::array_t<wp::float32> & adj_colour_weights,
    wp::array_t<wp::vec_t<3, wp::int32>> & adj_spectral_surface,
    wp::int32 & adj_spectral_panes,
    wp::array_t<wp::int32> & adj_light_group,
    wp::array_t<wp::int32> & adj_patch_base,
    GuideRec_b7ff9d66 & adj_guide,
    wp::array_t<wp::float32> & adj_pick_factor,
    wp::array_t<wp::vec_t<2, wp::float32>> & adj_pick_tally,
    wp::int32 & adj_n_patch_pick,
    wp::array_t<wp::float32> & adj_patch_pick_factor,
    wp::array_t<wp::vec_t<3, wp::float32>> & adj_patch_pick_tally,
    wp::array_t<OpticsRec_3192f450> & adj_optics,
    SceneRec_19d73428 & adj_ret)
{
    adj_mesh += adj_ret.mesh;
    adj_has_mesh += adj_ret.has_mesh;
    adj_points = adj_ret.points;
    adj_tris = adj_ret.tris;
    adj_albedo = adj_ret.albedo;
    adj_emission = adj_ret.emission;
    adj_two_sided = adj_ret.two_sided;
    adj_surfaces += adj_ret.surfaces;
    adj_surf_id = adj_ret.surf_id;
    adj_surf_side = adj_ret.surf_side;
    adj_surf = adj_ret.surf;
    adj_n_glints += adj_ret.n_glints;
    adj_glints = adj_ret.glints;
    adj_tex_id = adj_ret.tex_id;
    adj_tex_uv = adj_ret.tex_uv;
    adj_tex = adj_ret.tex;
    adj_texels = adj_ret.texels;
    adj_n_mirror_planes += adj_ret.n_mirror_planes;
    adj_mirror_planes = adj_ret.mirror_planes;
    adj_face_mirror = adj_ret.face_mirror;
    adj_plane_mirror = adj_ret.plane_mirror;
    adj_n_shaded += adj_ret.n_shaded;
    adj_shade_id = adj_ret.shade_id;
    adj_shade_n = adj_ret.shade_n;
    adj_n_curves += adj_ret.n_curves;
    adj_face_curve = adj_ret.face_curve;
    adj_curve_sphere = adj_ret.curve_sphere;
    adj_emit_tris = adj_ret.emit_tris;
    adj_emit_cdf = adj_ret.emit_cdf;
    adj_emit_prob = adj_ret.emit_prob;
    adj_n_pieces += adj_ret.n_pieces;
    adj_emit_piece = adj_ret.emit_piece;
    adj_piece_first = adj_ret.piece_first;
    adj_piece_count = adj_ret.piece_count;
    adj_piece_centre = adj_ret.piece_centre;
    adj_piece_normal = adj_ret.piece_normal;
    adj_piece_shape = adj_ret.piece_shape;
    adj_piece_factor = adj_ret.piece_factor;
    adj_piece_power = adj_ret.piece_power;
    adj_piece_tally = adj_ret.piece_tally;
    adj_lights = adj_ret.lights;
    adj_n_lights += adj_ret.n_lights;
    adj_eps += adj_ret.eps;
    adj_ray_counts = adj_ret.ray_counts;
    adj_light_mask = adj_ret.light_mask;
    adj_spectral_reflectance = adj_ret.spectral_reflectance;
    adj_spectral_face = adj_ret.spectral_face;
    adj_spectral_emission = adj_ret.spectral_emission;
    adj_spectral_face_emission = adj_ret.spectral_face_emission;
    adj_response_weights = adj_ret.response_weights;
    adj_response_lanes = adj_ret.response_lanes;
    adj_colour_weights = adj_ret.colour_weights;
    adj_spectral_surface = adj_ret.spectral_surface;
    adj_spectral_panes += adj_ret.spectral_panes;
    adj_light_group = adj_ret.light_group;
    adj_patch_base = adj_ret.patch_base;
    adj_guide += adj_ret.guide;
    adj_pick_factor = adj_ret.pick_factor;
    adj_pick_tally = adj_ret.pick_tally;
    adj_n_patch_pick += adj_ret.n_patch_pick;
    adj_patch_pick_factor = adj_ret.patch_pick_factor;
    adj_patch_pick_tally = adj_ret.patch_pick_tally;
    adj_optics = adj_ret.optics;
}

// Required when compiling adjoints.
CUDA_CALLABLE SceneRec_19d73428 add(const SceneRec_19d73428& a, const SceneRec_19d73428& b)
{
    return SceneRec_19d73428();
}

CUDA_CALLABLE void adj_atomic_add(SceneRec_19d73428* p, SceneRec_19d73428 t)
{
    wp::adj_atomic_add(&p->mesh, t.mesh);
    wp::adj_atomic_add(&p->has_mesh, t.has_mesh);
    wp::adj_atomic_add(&p->points, t.points);
    wp::adj_atomic_add(&p->tris, t.tris);
    wp::adj_atomic_add(&p->albedo, t.albedo);
    wp::adj_atomic_add(&p->emission, t.emission);
    wp::adj_atomic_add(&p->two_sided, t.two_sided);
    wp::adj_atomic_add(&p->surfaces, t.surfaces);
    wp::adj_atomic_add(&p->surf_id, t.surf_id);
    wp::adj_atomic_add(&p->surf_side, t.surf_side);
    wp::adj_atomic_add(&p->surf, t.surf);
    wp::adj_atomic_add(&p->n_glints, t.n_glints);
    wp::adj_atomic_add(&p->glints, t.glints);
    wp::adj_atomic_add(&p->tex_id, t.tex_id);
    wp::adj_atomic_add(&p->tex_uv, t.tex_uv);
    wp::adj_atomic_add(&p->tex, t.tex);
    wp::adj_atomic_add(&p->texels, t.texels);
    wp::adj_atomic_add(&p->n_mirror_planes, t.n_mirror_planes);
    wp::adj_atomic_add(&p->mirror_planes, t.mirror_planes);
    wp::adj_atomic_add(&p->face_mirror, t.face_mirror);
    wp::adj_atomic_add(&p->plane_mirror, t.plane_mirror);
    wp::adj_atomic_add(&p->n_shaded, t.n_shaded);
    wp::adj_atomic_add(&p->shade_id, t.shade_id);
    wp::adj_atomic_add(&p->shade_n, t.shade_n);
    wp::adj_atomic_add(&p->n_curves, t.n_curves);
    wp::adj_atomic_add(&p->face_curve, t.face_curve);
    wp::adj_atomic_add(&p->curve_sphere, t.curve_sphere);
    wp::adj_atomic_add(&p->emit_tris, t.emit_tris);
    wp::adj_atomic_add(&p->emit_cdf, t.emit_cdf);
    wp::adj_atomic_add(&p->emit_prob, t.emit_prob);
    wp::adj_atomic_add(&p->n_pieces, t.n_pieces);
    wp::adj_atomic_add(&p->emit_piece, t.emit_piece);
    wp::adj_atomic_add(&p->piece_first, t.piece_first);
    wp::adj_atomic_add(&p->piece_count, t.piece_count);
    wp::adj_atomic_add(&p->piece_centre, t.piece_centre);
    wp::adj_atomic_add(&p->piece_normal, t.piece_normal);
    wp::adj_atomic_add(&p->piece_shape, t.piece_shape);
    wp::adj_atomic_add(&p->piece_factor, t.piece_factor);
    wp::adj_atomic_add(&p->piece_power, t.piece_power);
    wp::adj_atomic_add(&p->piece_tally, t.piece_tally);
    wp::adj_atomic_add(&p->lights, t.lights);
    wp::adj_atomic_add(&p->n_lights, t.n_lights);
    wp::adj_atomic_add(&p->eps, t.eps);
    wp::adj_atomic_add(&p->ray_counts, t.ray_counts);
    wp::adj_atomic_add(&p->light_mask, t.light_mask);
    wp::adj_atomic_add(&p->spectral_reflectance, t.spectral_reflectance);
    wp::adj_atomic_add(&p->spectral_face, t.spectral_face);
    wp::adj_atomic_add(&p->spectral_emission, t.spectral_emission);
    wp::adj_atomic_add(&p->spectral_face_emission, t.spectral_face_emission);
    wp::adj_atomic_add(&p->response_weights, t.response_weights);
    wp::adj_atomic_add(&p->response_lanes, t.response_lanes);
    wp::adj_atomic_add(&p->colour_weights, t.colour_weights);
    wp::adj_atomic_add(&p->spectral_surface, t.spectral_surface);
    wp::adj_atomic_add(&p->spectral_panes, t.spectral_panes);
    wp::adj_atomic_add(&p->light_group, t.light_group);
    wp::adj_atomic_add(&p->patch_base, t.patch_base);
    adj_atomic_add(&p->guide, t.guide);
    wp::adj_atomic_add(&p->pick_factor, t.pick_factor);
    wp::adj_atomic_add(&p->pick_tally, t.pick_tally);
    wp::adj_atomic_add(&p->n_patch_pick, t.n_patch_pick);
    wp::adj_atomic_add(&p->patch_pick_factor, t.patch_pick_factor);
    wp::adj_atomic_add(&p->patch_pick_tally, t.patch_pick_tally);
    wp::adj_atomic_add(&p->optics, t.optics);
}




struct SphRect_7f5b29ec
{
    wp::vec_t<3, wp::float32> o;
    wp::vec_t<3, wp::float32> x;
    wp::vec_t<3, wp::float32> y;
    wp::vec_t<3, wp::float32> z;
    wp::float32 x0;
    wp::float32 y0;
    wp::float32 x1;
    wp::float32 y1;
    wp::float32 z0;
    wp::float32 b0;
    wp::float32 b1;
    wp::float32 k;
    wp::float32 solid_angle;


    SphRect_7f5b29ec() = default;
    CUDA_CALLABLE SphRect_7f5b29ec(wp::vec_t<3, wp::float32> const& o,
    wp::vec_t<3, wp::float32> const& x = {},
    wp::vec_t<3, wp::float32> const& y = {},
    wp::vec_t<3, wp::float32> const& z = {},
    wp::float32 const& x0 = {},
    wp::float32 const& y0 = {},
    wp::float32 const& x1 = {},
    wp::float32 const& y1 = {},
    wp::float32 const& z0 = {},
    wp::float32 const& b0 = {},
    wp::float32 const& b1 = {},
    wp::float32 const& k = {},
    wp::float32 const& solid_angle = {})
        : o{o}
        , x{x}
        , y{y}
        , z{z}
        , x0{x0}
        , y0{y0}
        , x1{x1}
        , y1{y1}
        , z0{z0}
        , b0{b0}
        , b1{b1}
        , k{k}
        , solid_angle{solid_angle}

    {
    }

    CUDA_CALLABLE SphRect_7f5b29ec& operator += (const SphRect_7f5b29ec& rhs)
    {    o += rhs.o;
    x += rhs.x;
    y += rhs.y;
    z += rhs.z;
    x0 += rhs.x0;
    y0 += rhs.y0;
    x1 += rhs.x1;
    y1 += rhs.y1;
    z0 += rhs.z0;
    b0 += rhs.b0;
    b1 += rhs.b1;
    k += rhs.k;
    solid_angle += rhs.solid_angle;

        return *this;}

};

static CUDA_CALLABLE void adj_SphRect_7f5b29ec(wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::vec_t<3, wp::float32> & adj_o,
    wp::vec_t<3, wp::float32> & adj_x,
    wp::vec_t<3, wp::float32> & adj_y,
    wp::vec_t<3, wp::float32> & adj_z,
    wp::float32 & adj_x0,
    wp::float32 & adj_y0,
    wp::float32 & adj_x1,
    wp::float32 & adj_y1,
    wp::float32 & adj_z0,
    wp::float32 & adj_b0,
    wp::float32 & adj_b1,
    wp::float32 & adj_k,
    wp::float32 & adj_solid_angle,
    SphRect_7f5b29ec & adj_ret)
{
    adj_o += adj_ret.o;
    adj_x += adj_ret.x;
    adj_y += adj_ret.y;
    adj_z += adj_ret.z;
    adj_x0 += adj_ret.x0;
    adj_y0 += adj_ret.y0;
    adj_x1 += adj_ret.x1;
    adj_y1 += adj_ret.y1;
    adj_z0 += adj_ret.z0;
    adj_b0 += adj_ret.b0;
    adj_b1 += adj_ret.b1;
    adj_k += adj_ret.k;
    adj_solid_angle += adj_ret.solid_angle;
}

// Required when compiling adjoints.
CUDA_CALLABLE SphRect_7f5b29ec add(const SphRect_7f5b29ec& a, const SphRect_7f5b29ec& b)
{
    return SphRect_7f5b29ec();
}

CUDA_CALLABLE void adj_atomic_add(SphRect_7f5b29ec* p, SphRect_7f5b29ec t)
{
    wp::adj_atomic_add(&p->o, t.o);
    wp::adj_atomic_add(&p->x, t.x);
    wp::adj_atomic_add(&p->y, t.y);
    wp::adj_atomic_add(&p->z, t.z);
    wp::adj_atomic_add(&p->x0, t.x0);
    wp::adj_atomic_add(&p->y0, t.y0);
    wp::adj_atomic_add(&p->x1, t.x1);
    wp::adj_atomic_add(&p->y1, t.y1);
    wp::adj_atomic_add(&p->z0, t.z0);
    wp::adj_atomic_add(&p->b0, t.b0);
    wp::adj_atomic_add(&p->b1, t.b1);
    wp::adj_atomic_add(&p->k, t.k);
    wp::adj_atomic_add(&p->solid_angle, t.solid_angle);
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




struct PiecePick_dedfee88
{
    wp::int32 k;
    wp::float32 prob;
    wp::float32 u;


    PiecePick_dedfee88() = default;
    CUDA_CALLABLE PiecePick_dedfee88(wp::int32 const& k,
    wp::float32 const& prob = {},
    wp::float32 const& u = {})
        : k{k}
        , prob{prob}
        , u{u}

    {
    }

    CUDA_CALLABLE PiecePick_dedfee88& operator += (const PiecePick_dedfee88& rhs)
    {    k += rhs.k;
    prob += rhs.prob;
    u += rhs.u;

        return *this;}

};

static CUDA_CALLABLE void adj_PiecePick_dedfee88(wp::int32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 & adj_k,
    wp::float32 & adj_prob,
    wp::float32 & adj_u,
    PiecePick_dedfee88 & adj_ret)
{
    adj_k += adj_ret.k;
    adj_prob += adj_ret.prob;
    adj_u += adj_ret.u;
}

// Required when compiling adjoints.
CUDA_CALLABLE PiecePick_dedfee88 add(const PiecePick_dedfee88& a, const PiecePick_dedfee88& b)
{
    return PiecePick_dedfee88();
}

CUDA_CALLABLE void adj_atomic_add(PiecePick_dedfee88* p, PiecePick_dedfee88 t)
{
    wp::adj_atomic_add(&p->k, t.k);
    wp::adj_atomic_add(&p->prob, t.prob);
    wp::adj_atomic_add(&p->u, t.u);
}




// /work/main/simulator/kernels/sampling.py:133
static wp::vec_t<3, wp::float32> sample_uniform_cone_0(
    wp::vec_t<2, wp::float32> var_u,
    wp::float32 var_one_minus_cos_max)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::float32 var_1;
    wp::float32 var_2;
    const wp::float32 var_3 = 1.0;
    wp::float32 var_4;
    const wp::float32 var_5 = 0.0;
    const wp::float32 var_6 = 2.0;
    wp::float32 var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 6.283185307179586;
    const wp::int32 var_12 = 1;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::float32 var_18;
    wp::vec_t<3, wp::float32> var_19;
    //---------
    // forward
    // def sample_uniform_cone(u: wp.vec2, one_minus_cos_max: float) -> wp.vec3:              <L 134>
    // omc = u[0] * one_minus_cos_max  # 1 − cosθ, uniform in [0, 1 − cosθmax]                <L 141>
    var_1 = wp::extract(var_u, var_0);
    var_2 = wp::mul(var_1, var_one_minus_cos_max);
    // cos_t = 1.0 - omc                                                                      <L 142>
    var_4 = wp::sub(var_3, var_2);
    // sin_t = wp.sqrt(wp.max(0.0, omc * (2.0 - omc)))                                        <L 143>
    var_7 = wp::sub(var_6, var_2);
    var_8 = wp::mul(var_2, var_7);
    var_9 = wp::max(var_5, var_8);
    var_10 = wp::sqrt(var_9);
    // phi = TWO_PI * u[1]                                                                    <L 144>
    var_13 = wp::extract(var_u, var_12);
    var_14 = wp::mul(var_11, var_13);
    // return wp.vec3(sin_t * wp.cos(phi), sin_t * wp.sin(phi), cos_t)                        <L 145>
    var_15 = wp::cos(var_14);
    var_16 = wp::mul(var_10, var_15);
    var_17 = wp::sin(var_14);
    var_18 = wp::mul(var_10, var_17);
    var_19 = wp::vec_t<3, wp::float32>(var_16, var_18, var_4);
    return var_19;
}


// /work/main/simulator/kernels/sampling.py:148
static wp::float32 pdf_uniform_cone_0(
    wp::float32 var_one_minus_cos_max)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 1.0;
    const wp::float32 var_1 = 6.283185307179586;
    wp::float32 var_2;
    wp::float32 var_3;
    //---------
    // forward
    // def pdf_uniform_cone(one_minus_cos_max: float) -> float:                               <L 149>
    // return 1.0 / (TWO_PI * one_minus_cos_max)                                              <L 151>
    var_2 = wp::mul(var_1, var_one_minus_cos_max);
    var_3 = wp::div(var_0, var_2);
    return var_3;
}


// /work/main/simulator/kernels/sampling.py:99
static wp::vec_t<2, wp::float32> sample_concentric_disk_0(
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 2.0;
    const wp::int32 var_1 = 0;
    wp::float32 var_2;
    wp::float32 var_3;
    const wp::float32 var_4 = 1.0;
    wp::float32 var_5;
    const wp::float32 var_6 = 2.0;
    const wp::int32 var_7 = 1;
    wp::float32 var_8;
    wp::float32 var_9;
    const wp::float32 var_10 = 1.0;
    wp::float32 var_11;
    bool var_12;
    const wp::float32 var_13 = 0.0;
    bool var_14;
    const wp::float32 var_15 = 0.0;
    bool var_16;
    const wp::float32 var_17 = 0.0;
    const wp::float32 var_18 = 0.0;
    wp::vec_t<2, wp::float32> var_19;
    const wp::float32 var_20 = 0.0;
    wp::float32 var_21;
    const wp::float32 var_22 = 0.0;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32 var_25;
    bool var_26;
    wp::float32 var_27;
    const wp::float32 var_28 = 3.141592653589793;
    const wp::float32 var_29 = 4.0;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32 var_33;
    const wp::float32 var_34 = 3.141592653589793;
    const wp::float32 var_35 = 2.0;
    wp::float32 var_36;
    const wp::float32 var_37 = 4.0;
    wp::float32 var_38;
    wp::float32 var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32 var_45;
    wp::float32 var_46;
    wp::float32 var_47;
    wp::float32 var_48;
    wp::vec_t<2, wp::float32> var_49;
    //---------
    // forward
    // def sample_concentric_disk(u: wp.vec2) -> wp.vec2:                                     <L 100>
    // a = 2.0 * u[0] - 1.0                                                                   <L 102>
    var_2 = wp::extract(var_u, var_1);
    var_3 = wp::mul(var_0, var_2);
    var_5 = wp::sub(var_3, var_4);
    // b = 2.0 * u[1] - 1.0                                                                   <L 103>
    var_8 = wp::extract(var_u, var_7);
    var_9 = wp::mul(var_6, var_8);
    var_11 = wp::sub(var_9, var_10);
    // if a == 0.0 and b == 0.0:                                                              <L 104>
    var_14 = (var_5 == var_13);
    var_12 = var_14;
    if (var_12) {
        var_16 = (var_11 == var_15);
        var_12 = var_12 && var_16;
    }
    if (var_12) {
        // return wp.vec2(0.0, 0.0)                                                           <L 105>
        var_19 = wp::vec_t<2, wp::float32>(var_17, var_18);
        return var_19;
    }
    // r = float(0.0)                                                                         <L 106>
    var_21 = wp::float(var_20);
    // phi = float(0.0)                                                                       <L 107>
    var_23 = wp::float(var_22);
    // if wp.abs(a) > wp.abs(b):                                                              <L 108>
    var_24 = wp::abs(var_5);
    var_25 = wp::abs(var_11);
    var_26 = (var_24 > var_25);
    if (var_26) {
        // r = a                                                                              <L 109>
        var_27 = wp::copy(var_5);
        // phi = (PI / 4.0) * (b / a)                                                         <L 110>
        var_30 = wp::div(var_28, var_29);
        var_31 = wp::div(var_11, var_5);
        var_32 = wp::mul(var_30, var_31);
    }
    if (!var_26) {
        // r = b                                                                              <L 112>
        var_33 = wp::copy(var_11);
        // phi = (PI / 2.0) - (PI / 4.0) * (a / b)                                            <L 113>
        var_36 = wp::div(var_34, var_35);
        var_38 = wp::div(var_34, var_37);
        var_39 = wp::div(var_5, var_11);
        var_40 = wp::mul(var_38, var_39);
        var_41 = wp::sub(var_36, var_40);
    }
    var_42 = wp::where(var_26, var_27, var_33);
    var_43 = wp::where(var_26, var_32, var_41);
    var_44 = wp::where(var_26, var_28, var_34);
    // return wp.vec2(r * wp.cos(phi), r * wp.sin(phi))                                       <L 114>
    var_45 = wp::cos(var_43);
    var_46 = wp::mul(var_42, var_45);
    var_47 = wp::sin(var_43);
    var_48 = wp::mul(var_42, var_47);
    var_49 = wp::vec_t<2, wp::float32>(var_46, var_48);
    return var_49;
}


// /work/main/simulator/kernels/lights/base.py:217
static LightSample_1981fb4b empty_sample_0(
    )
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    const wp::float32 var_1 = 0.0;
    const wp::float32 var_2 = 0.0;
    const wp::float32 var_3 = 1.0;
    wp::vec_t<3, wp::float32> var_4;
    const wp::float32 var_5 = 0.0;
    const wp::float32 var_6 = 0.0;
    const wp::float32 var_7 = 0.0;
    wp::vec_t<2, wp::float32> var_8;
    const wp::float32 var_9 = 0.0;
    const wp::int32 var_10 = -1;
    //---------
    // forward
    // def empty_sample() -> LightSample:                                                     <L 218>
    // s = LightSample()                                                                      <L 219>
    var_0 = LightSample_1981fb4b();
    // s.wi = wp.vec3(0.0, 0.0, 1.0)                                                          <L 220>
    var_4 = wp::vec_t<3, wp::float32>(var_1, var_2, var_3);
    var_0.wi = var_4;
    // s.dist = 0.0                                                                           <L 221>
    var_0.dist = var_5;
    // s.value = wp.vec2(0.0, 0.0)                                                            <L 222>
    var_8 = wp::vec_t<2, wp::float32>(var_6, var_7);
    var_0.value = var_8;
    // s.pdf = 0.0                                                                            <L 223>
    var_0.pdf = var_9;
    // s.tri = -1                                                                             <L 224>
    var_0.tri = var_10;
    // return s                                                                               <L 225>
    return var_0;
}


// /work/main/simulator/kernels/lights/point.py:15
static LightSample_1981fb4b sample_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::float32 var_4;
    const wp::float32 var_5 = 0.0;
    bool var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32>* var_8;
    wp::float32 var_9;
    wp::vec_t<3, wp::float32> var_10;
    const wp::float32 var_11 = 0.0;
    bool var_12;
    wp::vec_t<2, wp::float32>* var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::vec_t<2, wp::float32> var_16;
    wp::vec_t<2, wp::float32> var_17;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 16>
    // s = empty_sample()                                                                     <L 18>
    var_0 = empty_sample_0();
    // d = l.position - p                                                                     <L 19>
    var_1 = &((var_l).position);
    var_3 = wp::load(var_1);
    var_2 = wp::sub(var_3, var_p);
    // dist = wp.length(d)                                                                    <L 20>
    var_4 = wp::length(var_2);
    // if dist <= 0.0:                                                                        <L 21>
    var_6 = (var_4 <= var_5);
    if (var_6) {
        // return s                                                                           <L 22>
        return var_0;
    }
    // s.wi = d / dist                                                                        <L 23>
    var_7 = wp::div(var_2, var_4);
    var_0.wi = var_7;
    // s.dist = dist                                                                          <L 24>
    var_0.dist = var_4;
    // cos_r = wp.dot(s.wi, n)                                                                <L 25>
    var_8 = &((var_0).wi);
    var_10 = wp::load(var_8);
    var_9 = wp::dot(var_10, var_n);
    // if cos_r > 0.0:                                                                        <L 26>
    var_12 = (var_9 > var_11);
    if (var_12) {
        // s.value = l.emission * (cos_r / (dist * dist))  # E = I·cosξ/d²                    <L 27>
        var_13 = &((var_l).emission);
        var_14 = wp::mul(var_4, var_4);
        var_15 = wp::div(var_9, var_14);
        var_17 = wp::load(var_13);
        var_16 = wp::mul(var_17, var_15);
        var_0.value = var_16;
    }
    // return s                                                                               <L 28>
    return var_0;
}


// /work/main/simulator/kernels/sampling.py:154
static wp::float32 one_minus_cos_from_sin2_0(
    wp::float32 var_sin2)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 1.0;
    wp::float32 var_1;
    const wp::float32 var_2 = 1.0;
    const wp::float32 var_3 = 1.0;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    //---------
    // forward
    // def one_minus_cos_from_sin2(sin2: float) -> float:                                     <L 155>
    // s2 = wp.min(sin2, 1.0)                                                                 <L 157>
    var_1 = wp::min(var_sin2, var_0);
    // return s2 / (1.0 + wp.sqrt(1.0 - s2))                                                  <L 158>
    var_4 = wp::sub(var_3, var_1);
    var_5 = wp::sqrt(var_4);
    var_6 = wp::add(var_2, var_5);
    var_7 = wp::div(var_1, var_6);
    return var_7;
}


// /work/main/simulator/kernels/lights/sphere.py:18
static wp::float32 cone_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::float32 var_3;
    wp::float32* var_4;
    wp::float32* var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    bool var_9;
    const wp::float32 var_10 = 0.0;
    wp::float32 var_11;
    wp::float32 var_12;
    //---------
    // forward
    // def cone(l: LightRec, p: wp.vec3) -> float:                                            <L 19>
    // d2 = wp.length_sq(l.position - p)                                                      <L 21>
    var_0 = &((var_l).position);
    var_2 = wp::load(var_0);
    var_1 = wp::sub(var_2, var_p);
    var_3 = wp::length_sq(var_1);
    // r2 = l.radius * l.radius                                                               <L 22>
    var_4 = &((var_l).radius);
    var_5 = &((var_l).radius);
    var_7 = wp::load(var_4);
    var_8 = wp::load(var_5);
    var_6 = wp::mul(var_7, var_8);
    // if d2 <= r2:                                                                           <L 23>
    var_9 = (var_3 <= var_6);
    if (var_9) {
        // return 0.0                                                                         <L 24>
        return var_10;
    }
    // return one_minus_cos_from_sin2(r2 / d2)                                                <L 25>
    var_11 = wp::div(var_6, var_3);
    var_12 = one_minus_cos_from_sin2_0(var_11);
    return var_12;
}


// /work/main/simulator/kernels/sampling.py:73
static wp::vec_t<3, wp::float32> frame_x_0(
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    const wp::float32 var_4 = 1.0;
    const wp::float32 var_5 = -1.0;
    wp::float32 var_6;
    const wp::float32 var_7 = -1.0;
    const wp::int32 var_8 = 2;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    const wp::int32 var_12 = 0;
    wp::float32 var_13;
    const wp::int32 var_14 = 1;
    wp::float32 var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    const wp::float32 var_18 = 1.0;
    const wp::int32 var_19 = 0;
    wp::float32 var_20;
    wp::float32 var_21;
    const wp::int32 var_22 = 0;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    const wp::int32 var_29 = 0;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::vec_t<3, wp::float32> var_32;
    //---------
    // forward
    // def frame_x(n: wp.vec3) -> wp.vec3:                                                    <L 74>
    // s = wp.where(n[2] >= 0.0, 1.0, -1.0)                                                   <L 76>
    var_1 = wp::extract(var_n, var_0);
    var_3 = (var_1 >= var_2);
    var_6 = wp::where(var_3, var_4, var_5);
    // a = -1.0 / (s + n[2])                                                                  <L 77>
    var_9 = wp::extract(var_n, var_8);
    var_10 = wp::add(var_6, var_9);
    var_11 = wp::div(var_7, var_10);
    // b = n[0] * n[1] * a                                                                    <L 78>
    var_13 = wp::extract(var_n, var_12);
    var_15 = wp::extract(var_n, var_14);
    var_16 = wp::mul(var_13, var_15);
    var_17 = wp::mul(var_16, var_11);
    // return wp.vec3(1.0 + s * n[0] * n[0] * a, s * b, -s * n[0])                            <L 79>
    var_20 = wp::extract(var_n, var_19);
    var_21 = wp::mul(var_6, var_20);
    var_23 = wp::extract(var_n, var_22);
    var_24 = wp::mul(var_21, var_23);
    var_25 = wp::mul(var_24, var_11);
    var_26 = wp::add(var_18, var_25);
    var_27 = wp::mul(var_6, var_17);
    var_28 = wp::neg(var_6);
    var_30 = wp::extract(var_n, var_29);
    var_31 = wp::mul(var_28, var_30);
    var_32 = wp::vec_t<3, wp::float32>(var_26, var_27, var_31);
    return var_32;
}


// /work/main/simulator/kernels/sampling.py:82
static wp::vec_t<3, wp::float32> frame_y_0(
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 2;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    const wp::float32 var_4 = 1.0;
    const wp::float32 var_5 = -1.0;
    wp::float32 var_6;
    const wp::float32 var_7 = -1.0;
    const wp::int32 var_8 = 2;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    const wp::int32 var_12 = 0;
    wp::float32 var_13;
    const wp::int32 var_14 = 1;
    wp::float32 var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    const wp::int32 var_18 = 1;
    wp::float32 var_19;
    const wp::int32 var_20 = 1;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    const wp::int32 var_25 = 1;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::vec_t<3, wp::float32> var_28;
    //---------
    // forward
    // def frame_y(n: wp.vec3) -> wp.vec3:                                                    <L 83>
    // s = wp.where(n[2] >= 0.0, 1.0, -1.0)                                                   <L 85>
    var_1 = wp::extract(var_n, var_0);
    var_3 = (var_1 >= var_2);
    var_6 = wp::where(var_3, var_4, var_5);
    // a = -1.0 / (s + n[2])                                                                  <L 86>
    var_9 = wp::extract(var_n, var_8);
    var_10 = wp::add(var_6, var_9);
    var_11 = wp::div(var_7, var_10);
    // b = n[0] * n[1] * a                                                                    <L 87>
    var_13 = wp::extract(var_n, var_12);
    var_15 = wp::extract(var_n, var_14);
    var_16 = wp::mul(var_13, var_15);
    var_17 = wp::mul(var_16, var_11);
    // return wp.vec3(b, s + n[1] * n[1] * a, -n[1])                                          <L 88>
    var_19 = wp::extract(var_n, var_18);
    var_21 = wp::extract(var_n, var_20);
    var_22 = wp::mul(var_19, var_21);
    var_23 = wp::mul(var_22, var_11);
    var_24 = wp::add(var_6, var_23);
    var_26 = wp::extract(var_n, var_25);
    var_27 = wp::neg(var_26);
    var_28 = wp::vec_t<3, wp::float32>(var_17, var_24, var_27);
    return var_28;
}


// /work/main/simulator/kernels/sampling.py:91
static wp::vec_t<3, wp::float32> to_world_0(
    wp::vec_t<3, wp::float32> var_local,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::float32 var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32> var_3;
    const wp::int32 var_4 = 1;
    wp::float32 var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    const wp::int32 var_9 = 2;
    wp::float32 var_10;
    wp::vec_t<3, wp::float32> var_11;
    wp::vec_t<3, wp::float32> var_12;
    //---------
    // forward
    // def to_world(local: wp.vec3, n: wp.vec3) -> wp.vec3:                                   <L 92>
    // return local[0] * frame_x(n) + local[1] * frame_y(n) + local[2] * n                    <L 93>
    var_1 = wp::extract(var_local, var_0);
    var_2 = frame_x_0(var_n);
    var_3 = wp::mul(var_1, var_2);
    var_5 = wp::extract(var_local, var_4);
    var_6 = frame_y_0(var_n);
    var_7 = wp::mul(var_5, var_6);
    var_8 = wp::add(var_3, var_7);
    var_10 = wp::extract(var_local, var_9);
    var_11 = wp::mul(var_10, var_n);
    var_12 = wp::add(var_8, var_11);
    return var_12;
}


// /work/main/simulator/kernels/lights/sphere.py:28
static LightSample_1981fb4b sample_7(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::float32 var_1;
    const wp::float32 var_2 = 0.0;
    bool var_3;
    wp::vec_t<3, wp::float32>* var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    const wp::int32 var_8 = 0;
    wp::float32 var_9;
    const wp::int32 var_10 = 1;
    wp::float32 var_11;
    wp::vec_t<2, wp::float32> var_12;
    wp::vec_t<3, wp::float32> var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::vec_t<3, wp::float32>* var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::float32 var_18;
    wp::float32* var_19;
    wp::float32* var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    const wp::float32 var_28 = 0.0;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    const wp::float32 var_32 = 0.0;
    wp::float32 var_33;
    wp::float32 var_34;
    wp::float32 var_35;
    const wp::float32 var_36 = 0.0;
    bool var_37;
    wp::vec_t<2, wp::float32>* var_38;
    wp::float32* var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    wp::vec_t<2, wp::float32> var_42;
    wp::vec_t<2, wp::float32> var_43;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 29>
    // s = empty_sample()                                                                     <L 30>
    var_0 = empty_sample_0();
    // omc = cone(l, p)                                                                       <L 31>
    var_1 = cone_0(var_l, var_p);
    // if omc <= 0.0:                                                                         <L 32>
    var_3 = (var_1 <= var_2);
    if (var_3) {
        // return s  # inside a sphere light: it emits outward only                           <L 33>
        return var_0;
    }
    // axis = wp.normalize(l.position - p)                                                    <L 34>
    var_4 = &((var_l).position);
    var_6 = wp::load(var_4);
    var_5 = wp::sub(var_6, var_p);
    var_7 = wp::normalize(var_5);
    // wi = to_world(sample_uniform_cone(wp.vec2(u[0], u[1]), omc), axis)                     <L 35>
    var_9 = wp::extract(var_u, var_8);
    var_11 = wp::extract(var_u, var_10);
    var_12 = wp::vec_t<2, wp::float32>(var_9, var_11);
    var_13 = sample_uniform_cone_0(var_12, var_1);
    var_14 = to_world_0(var_13, var_7);
    // oc = l.position - p                                                                    <L 37>
    var_15 = &((var_l).position);
    var_17 = wp::load(var_15);
    var_16 = wp::sub(var_17, var_p);
    // b = wp.dot(oc, wi)                                                                     <L 38>
    var_18 = wp::dot(var_16, var_14);
    // disc = l.radius * l.radius - (wp.length_sq(oc) - b * b)                                <L 39>
    var_19 = &((var_l).radius);
    var_20 = &((var_l).radius);
    var_22 = wp::load(var_19);
    var_23 = wp::load(var_20);
    var_21 = wp::mul(var_22, var_23);
    var_24 = wp::length_sq(var_16);
    var_25 = wp::mul(var_18, var_18);
    var_26 = wp::sub(var_24, var_25);
    var_27 = wp::sub(var_21, var_26);
    // t = b - wp.sqrt(wp.max(disc, 0.0))                                                     <L 40>
    var_29 = wp::max(var_27, var_28);
    var_30 = wp::sqrt(var_29);
    var_31 = wp::sub(var_18, var_30);
    // s.wi = wi                                                                              <L 41>
    var_0.wi = var_14;
    // s.dist = wp.max(t, 0.0)                                                                <L 42>
    var_33 = wp::max(var_31, var_32);
    var_0.dist = var_33;
    // s.pdf = pdf_uniform_cone(omc)                                                          <L 43>
    var_34 = pdf_uniform_cone_0(var_1);
    var_0.pdf = var_34;
    // cos_r = wp.dot(wi, n)                                                                  <L 44>
    var_35 = wp::dot(var_14, var_n);
    // if cos_r > 0.0:                                                                        <L 45>
    var_37 = (var_35 > var_36);
    if (var_37) {
        // s.value = l.emission * (cos_r / s.pdf)                                             <L 46>
        var_38 = &((var_l).emission);
        var_39 = &((var_0).pdf);
        var_41 = wp::load(var_39);
        var_40 = wp::div(var_35, var_41);
        var_43 = wp::load(var_38);
        var_42 = wp::mul(var_43, var_40);
        var_0.value = var_42;
    }
    // return s                                                                               <L 47>
    return var_0;
}


// /work/main/simulator/kernels/lights/base.py:309
static bool behind_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32>* var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32> var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    //---------
    // forward
    // def behind(l: LightRec, p: wp.vec3) -> bool:                                           <L 310>
    // return wp.dot(p - l.position, l.ez) >= 0.0                                             <L 312>
    var_0 = &((var_l).position);
    var_2 = wp::load(var_0);
    var_1 = wp::sub(var_p, var_2);
    var_3 = &((var_l).ez);
    var_5 = wp::load(var_3);
    var_4 = wp::dot(var_1, var_5);
    var_7 = (var_4 >= var_6);
    return var_7;
}


// /work/main/simulator/kernels/lights/rect.py:20
static wp::vec_t<3, wp::float32> corner_0(
    LightRec_73c30c8a var_l)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    const wp::float32 var_1 = 0.5;
    wp::float32* var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32>* var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32> var_9;
    const wp::float32 var_10 = 0.5;
    wp::float32* var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32>* var_14;
    wp::vec_t<3, wp::float32> var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    //---------
    // forward
    // def corner(l: LightRec) -> wp.vec3:                                                    <L 21>
    // return l.position - 0.5 * l.width * l.ex - 0.5 * l.height * l.ey                       <L 22>
    var_0 = &((var_l).position);
    var_2 = &((var_l).width);
    var_4 = wp::load(var_2);
    var_3 = wp::mul(var_1, var_4);
    var_5 = &((var_l).ex);
    var_7 = wp::load(var_5);
    var_6 = wp::mul(var_3, var_7);
    var_9 = wp::load(var_0);
    var_8 = wp::sub(var_9, var_6);
    var_11 = &((var_l).height);
    var_13 = wp::load(var_11);
    var_12 = wp::mul(var_10, var_13);
    var_14 = &((var_l).ey);
    var_16 = wp::load(var_14);
    var_15 = wp::mul(var_12, var_16);
    var_17 = wp::sub(var_8, var_15);
    return var_17;
}


// /work/main/simulator/kernels/sampling.py:197
static SphRect_7f5b29ec sphrect_setup_0(
    wp::vec_t<3, wp::float32> var_o,
    wp::vec_t<3, wp::float32> var_corner,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::float32 var_w,
    wp::float32 var_h)
{
    //---------
    // primal vars
    SphRect_7f5b29ec var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    wp::float32 var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::float32 var_11;
    wp::float32* var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32* var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::float32* var_18;
    wp::float32* var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32* var_23;
    wp::float32* var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32* var_28;
    wp::float32* var_29;
    wp::vec_t<3, wp::float32> var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32* var_33;
    wp::float32* var_34;
    wp::vec_t<3, wp::float32> var_35;
    wp::float32 var_36;
    wp::float32 var_37;
    wp::vec_t<3, wp::float32> var_38;
    wp::vec_t<3, wp::float32> var_39;
    wp::vec_t<3, wp::float32> var_40;
    wp::vec_t<3, wp::float32> var_41;
    wp::vec_t<3, wp::float32> var_42;
    wp::vec_t<3, wp::float32> var_43;
    wp::vec_t<3, wp::float32> var_44;
    wp::vec_t<3, wp::float32> var_45;
    wp::float32 var_46;
    wp::float32 var_47;
    const wp::float32 var_48 = -1.0;
    const wp::float32 var_49 = 1.0;
    wp::float32 var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::float32 var_53;
    const wp::float32 var_54 = -1.0;
    const wp::float32 var_55 = 1.0;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32 var_58;
    wp::float32 var_59;
    const wp::float32 var_60 = -1.0;
    const wp::float32 var_61 = 1.0;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    wp::float32 var_65;
    const wp::float32 var_66 = -1.0;
    const wp::float32 var_67 = 1.0;
    wp::float32 var_68;
    wp::float32 var_69;
    const wp::int32 var_70 = 2;
    wp::float32 var_71;
    const wp::int32 var_72 = 2;
    wp::float32 var_73;
    const wp::float32 var_74 = 6.283185307179586;
    wp::float32 var_75;
    wp::float32 var_76;
    wp::float32 var_77;
    wp::float32* var_78;
    wp::float32 var_79;
    wp::float32 var_80;
    //---------
    // forward
    // def sphrect_setup(o: wp.vec3, corner: wp.vec3, ex: wp.vec3, ey: wp.vec3, w: float, h: float) -> SphRect:       <L 198>
    // r = SphRect()                                                                          <L 205>
    var_0 = SphRect_7f5b29ec();
    // r.o = o                                                                                <L 206>
    var_0.o = var_o;
    // r.x = ex                                                                               <L 207>
    var_0.x = var_ex;
    // r.y = ey                                                                               <L 208>
    var_0.y = var_ey;
    // z = wp.cross(ex, ey)                                                                   <L 209>
    var_1 = wp::cross(var_ex, var_ey);
    // d = corner - o                                                                         <L 210>
    var_2 = wp::sub(var_corner, var_o);
    // r.x0 = wp.dot(d, ex)                                                                   <L 211>
    var_3 = wp::dot(var_2, var_ex);
    var_0.x0 = var_3;
    // r.y0 = wp.dot(d, ey)                                                                   <L 212>
    var_4 = wp::dot(var_2, var_ey);
    var_0.y0 = var_4;
    // z0 = wp.dot(d, z)                                                                      <L 213>
    var_5 = wp::dot(var_2, var_1);
    // if z0 > 0.0:                                                                           <L 214>
    var_7 = (var_5 > var_6);
    if (var_7) {
        // z0 = -z0                                                                           <L 215>
        var_8 = wp::neg(var_5);
        // z = -z                                                                             <L 216>
        var_9 = wp::neg(var_1);
    }
    var_10 = wp::where(var_7, var_9, var_1);
    var_11 = wp::where(var_7, var_8, var_5);
    // r.z = z                                                                                <L 217>
    var_0.z = var_10;
    // r.z0 = z0                                                                              <L 218>
    var_0.z0 = var_11;
    // r.x1 = r.x0 + w                                                                        <L 219>
    var_12 = &((var_0).x0);
    var_14 = wp::load(var_12);
    var_13 = wp::add(var_14, var_w);
    var_0.x1 = var_13;
    // r.y1 = r.y0 + h                                                                        <L 220>
    var_15 = &((var_0).y0);
    var_17 = wp::load(var_15);
    var_16 = wp::add(var_17, var_h);
    var_0.y1 = var_16;
    // v00 = wp.vec3(r.x0, r.y0, z0)                                                          <L 221>
    var_18 = &((var_0).x0);
    var_19 = &((var_0).y0);
    var_21 = wp::load(var_18);
    var_22 = wp::load(var_19);
    var_20 = wp::vec_t<3, wp::float32>(var_21, var_22, var_11);
    // v01 = wp.vec3(r.x0, r.y1, z0)                                                          <L 222>
    var_23 = &((var_0).x0);
    var_24 = &((var_0).y1);
    var_26 = wp::load(var_23);
    var_27 = wp::load(var_24);
    var_25 = wp::vec_t<3, wp::float32>(var_26, var_27, var_11);
    // v10 = wp.vec3(r.x1, r.y0, z0)                                                          <L 223>
    var_28 = &((var_0).x1);
    var_29 = &((var_0).y0);
    var_31 = wp::load(var_28);
    var_32 = wp::load(var_29);
    var_30 = wp::vec_t<3, wp::float32>(var_31, var_32, var_11);
    // v11 = wp.vec3(r.x1, r.y1, z0)                                                          <L 224>
    var_33 = &((var_0).x1);
    var_34 = &((var_0).y1);
    var_36 = wp::load(var_33);
    var_37 = wp::load(var_34);
    var_35 = wp::vec_t<3, wp::float32>(var_36, var_37, var_11);
    // n0 = wp.normalize(wp.cross(v00, v10))                                                  <L 225>
    var_38 = wp::cross(var_20, var_30);
    var_39 = wp::normalize(var_38);
    // n1 = wp.normalize(wp.cross(v10, v11))                                                  <L 226>
    var_40 = wp::cross(var_30, var_35);
    var_41 = wp::normalize(var_40);
    // n2 = wp.normalize(wp.cross(v11, v01))                                                  <L 227>
    var_42 = wp::cross(var_35, var_25);
    var_43 = wp::normalize(var_42);
    // n3 = wp.normalize(wp.cross(v01, v00))                                                  <L 228>
    var_44 = wp::cross(var_25, var_20);
    var_45 = wp::normalize(var_44);
    // g0 = wp.acos(wp.clamp(-wp.dot(n0, n1), -1.0, 1.0))                                     <L 229>
    var_46 = wp::dot(var_39, var_41);
    var_47 = wp::neg(var_46);
    var_50 = wp::clamp(var_47, var_48, var_49);
    var_51 = wp::acos(var_50);
    // g1 = wp.acos(wp.clamp(-wp.dot(n1, n2), -1.0, 1.0))                                     <L 230>
    var_52 = wp::dot(var_41, var_43);
    var_53 = wp::neg(var_52);
    var_56 = wp::clamp(var_53, var_54, var_55);
    var_57 = wp::acos(var_56);
    // g2 = wp.acos(wp.clamp(-wp.dot(n2, n3), -1.0, 1.0))                                     <L 231>
    var_58 = wp::dot(var_43, var_45);
    var_59 = wp::neg(var_58);
    var_62 = wp::clamp(var_59, var_60, var_61);
    var_63 = wp::acos(var_62);
    // g3 = wp.acos(wp.clamp(-wp.dot(n3, n0), -1.0, 1.0))                                     <L 232>
    var_64 = wp::dot(var_45, var_39);
    var_65 = wp::neg(var_64);
    var_68 = wp::clamp(var_65, var_66, var_67);
    var_69 = wp::acos(var_68);
    // r.b0 = n0[2]                                                                           <L 233>
    var_71 = wp::extract(var_39, var_70);
    var_0.b0 = var_71;
    // r.b1 = n2[2]                                                                           <L 234>
    var_73 = wp::extract(var_43, var_72);
    var_0.b1 = var_73;
    // r.k = TWO_PI - g2 - g3                                                                 <L 235>
    var_75 = wp::sub(var_74, var_63);
    var_76 = wp::sub(var_75, var_69);
    var_0.k = var_76;
    // r.solid_angle = g0 + g1 - r.k                                                          <L 236>
    var_77 = wp::add(var_51, var_57);
    var_78 = &((var_0).k);
    var_80 = wp::load(var_78);
    var_79 = wp::sub(var_77, var_80);
    var_0.solid_angle = var_79;
    // return r                                                                               <L 237>
    return var_0;
}


// /work/main/simulator/kernels/lights/base.py:261
static LightSample_1981fb4b area_sample_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_q,
    wp::vec_t<3, wp::float32> var_nl)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::float32 var_2;
    const wp::float32 var_3 = 0.0;
    bool var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    const wp::float32 var_8 = 0.0;
    bool var_9;
    wp::float32 var_10;
    wp::float32* var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    const wp::float32 var_16 = 0.0;
    bool var_17;
    wp::vec_t<2, wp::float32>* var_18;
    wp::float32* var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::vec_t<2, wp::float32> var_22;
    wp::vec_t<2, wp::float32> var_23;
    //---------
    // forward
    // def area_sample(l: LightRec, p: wp.vec3, n: wp.vec3, q: wp.vec3, nl: wp.vec3) -> LightSample:       <L 262>
    // s = empty_sample()                                                                     <L 266>
    var_0 = empty_sample_0();
    // d = q - p                                                                              <L 267>
    var_1 = wp::sub(var_q, var_p);
    // dist = wp.length(d)                                                                    <L 268>
    var_2 = wp::length(var_1);
    // if dist <= 0.0:                                                                        <L 269>
    var_4 = (var_2 <= var_3);
    if (var_4) {
        // return s                                                                           <L 270>
        return var_0;
    }
    // wi = d / dist                                                                          <L 271>
    var_5 = wp::div(var_1, var_2);
    // cos_l = -wp.dot(wi, nl)                                                                <L 272>
    var_6 = wp::dot(var_5, var_nl);
    var_7 = wp::neg(var_6);
    // if cos_l <= 0.0:                                                                       <L 273>
    var_9 = (var_7 <= var_8);
    if (var_9) {
        // return s                                                                           <L 274>
        return var_0;
    }
    // s.wi = wi                                                                              <L 275>
    var_0.wi = var_5;
    // s.dist = dist                                                                          <L 276>
    var_0.dist = var_2;
    // s.pdf = dist * dist / (l.area * cos_l)                                                 <L 277>
    var_10 = wp::mul(var_2, var_2);
    var_11 = &((var_l).area);
    var_13 = wp::load(var_11);
    var_12 = wp::mul(var_13, var_7);
    var_14 = wp::div(var_10, var_12);
    var_0.pdf = var_14;
    // cos_r = wp.dot(wi, n)                                                                  <L 278>
    var_15 = wp::dot(var_5, var_n);
    // if cos_r > 0.0:                                                                        <L 279>
    var_17 = (var_15 > var_16);
    if (var_17) {
        // s.value = l.emission * (cos_r / s.pdf)                                             <L 280>
        var_18 = &((var_l).emission);
        var_19 = &((var_0).pdf);
        var_21 = wp::load(var_19);
        var_20 = wp::div(var_15, var_21);
        var_23 = wp::load(var_18);
        var_22 = wp::mul(var_23, var_20);
        var_0.value = var_22;
    }
    // return s                                                                               <L 281>
    return var_0;
}


// /work/main/simulator/kernels/sampling.py:240
static wp::vec_t<3, wp::float32> sphrect_sample_0(
    SphRect_7f5b29ec var_r,
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::float32 var_1;
    wp::float32* var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32* var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    wp::float32* var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32* var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::float32 var_16;
    const wp::float32 var_17 = 0.0;
    bool var_18;
    const wp::float32 var_19 = 1.0;
    const wp::float32 var_20 = -1.0;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32* var_23;
    wp::float32* var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    const wp::float32 var_31 = -1.0;
    const wp::float32 var_32 = 1.0;
    wp::float32 var_33;
    wp::float32* var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 1.0;
    wp::float32 var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    const wp::float32 var_42 = 1e-12;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32* var_45;
    wp::float32* var_46;
    wp::float32 var_47;
    wp::float32 var_48;
    wp::float32 var_49;
    wp::float32 var_50;
    wp::float32* var_51;
    wp::float32* var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::float32 var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32* var_58;
    wp::float32 var_59;
    wp::float32* var_60;
    wp::float32* var_61;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    wp::float32 var_65;
    wp::float32 var_66;
    wp::float32 var_67;
    wp::float32 var_68;
    wp::float32* var_69;
    wp::float32 var_70;
    wp::float32* var_71;
    wp::float32* var_72;
    wp::float32 var_73;
    wp::float32 var_74;
    wp::float32 var_75;
    wp::float32 var_76;
    wp::float32 var_77;
    wp::float32 var_78;
    wp::float32 var_79;
    const wp::int32 var_80 = 1;
    wp::float32 var_81;
    wp::float32 var_82;
    wp::float32 var_83;
    wp::float32 var_84;
    wp::float32 var_85;
    wp::float32* var_86;
    wp::float32 var_87;
    wp::float32 var_88;
    const wp::float32 var_89 = 1.0;
    const wp::float32 var_90 = 1e-06;
    wp::float32 var_91;
    bool var_92;
    wp::float32 var_93;
    const wp::float32 var_94 = 1.0;
    wp::float32 var_95;
    wp::float32 var_96;
    wp::float32 var_97;
    wp::float32 var_98;
    wp::float32* var_99;
    wp::float32* var_100;
    wp::float32 var_101;
    wp::float32 var_102;
    wp::float32 var_103;
    wp::vec_t<3, wp::float32>* var_104;
    wp::vec_t<3, wp::float32>* var_105;
    wp::vec_t<3, wp::float32> var_106;
    wp::vec_t<3, wp::float32> var_107;
    wp::vec_t<3, wp::float32> var_108;
    wp::vec_t<3, wp::float32> var_109;
    wp::vec_t<3, wp::float32>* var_110;
    wp::vec_t<3, wp::float32> var_111;
    wp::vec_t<3, wp::float32> var_112;
    wp::vec_t<3, wp::float32> var_113;
    wp::float32* var_114;
    wp::vec_t<3, wp::float32>* var_115;
    wp::vec_t<3, wp::float32> var_116;
    wp::float32 var_117;
    wp::vec_t<3, wp::float32> var_118;
    wp::vec_t<3, wp::float32> var_119;
    //---------
    // forward
    // def sphrect_sample(r: SphRect, u: wp.vec2) -> wp.vec3:                                 <L 241>
    // au = u[0] * r.solid_angle + r.k                                                        <L 245>
    var_1 = wp::extract(var_u, var_0);
    var_2 = &((var_r).solid_angle);
    var_4 = wp::load(var_2);
    var_3 = wp::mul(var_1, var_4);
    var_5 = &((var_r).k);
    var_7 = wp::load(var_5);
    var_6 = wp::add(var_3, var_7);
    // fu = (wp.cos(au) * r.b0 - r.b1) / wp.sin(au)                                           <L 246>
    var_8 = wp::cos(var_6);
    var_9 = &((var_r).b0);
    var_11 = wp::load(var_9);
    var_10 = wp::mul(var_8, var_11);
    var_12 = &((var_r).b1);
    var_14 = wp::load(var_12);
    var_13 = wp::sub(var_10, var_14);
    var_15 = wp::sin(var_6);
    var_16 = wp::div(var_13, var_15);
    // cu = wp.where(fu > 0.0, 1.0, -1.0) / wp.sqrt(fu * fu + r.b0 * r.b0)                    <L 247>
    var_18 = (var_16 > var_17);
    var_21 = wp::where(var_18, var_19, var_20);
    var_22 = wp::mul(var_16, var_16);
    var_23 = &((var_r).b0);
    var_24 = &((var_r).b0);
    var_26 = wp::load(var_23);
    var_27 = wp::load(var_24);
    var_25 = wp::mul(var_26, var_27);
    var_28 = wp::add(var_22, var_25);
    var_29 = wp::sqrt(var_28);
    var_30 = wp::div(var_21, var_29);
    // cu = wp.clamp(cu, -1.0, 1.0)                                                           <L 248>
    var_33 = wp::clamp(var_30, var_31, var_32);
    // xu = -(cu * r.z0) / wp.max(wp.sqrt(1.0 - cu * cu), 1.0e-12)                            <L 249>
    var_34 = &((var_r).z0);
    var_36 = wp::load(var_34);
    var_35 = wp::mul(var_33, var_36);
    var_37 = wp::neg(var_35);
    var_39 = wp::mul(var_33, var_33);
    var_40 = wp::sub(var_38, var_39);
    var_41 = wp::sqrt(var_40);
    var_43 = wp::max(var_41, var_42);
    var_44 = wp::div(var_37, var_43);
    // xu = wp.clamp(xu, r.x0, r.x1)                                                          <L 250>
    var_45 = &((var_r).x0);
    var_46 = &((var_r).x1);
    var_48 = wp::load(var_45);
    var_49 = wp::load(var_46);
    var_47 = wp::clamp(var_44, var_48, var_49);
    // d = wp.sqrt(xu * xu + r.z0 * r.z0)                                                     <L 251>
    var_50 = wp::mul(var_47, var_47);
    var_51 = &((var_r).z0);
    var_52 = &((var_r).z0);
    var_54 = wp::load(var_51);
    var_55 = wp::load(var_52);
    var_53 = wp::mul(var_54, var_55);
    var_56 = wp::add(var_50, var_53);
    var_57 = wp::sqrt(var_56);
    // h0 = r.y0 / wp.sqrt(d * d + r.y0 * r.y0)                                               <L 252>
    var_58 = &((var_r).y0);
    var_59 = wp::mul(var_57, var_57);
    var_60 = &((var_r).y0);
    var_61 = &((var_r).y0);
    var_63 = wp::load(var_60);
    var_64 = wp::load(var_61);
    var_62 = wp::mul(var_63, var_64);
    var_65 = wp::add(var_59, var_62);
    var_66 = wp::sqrt(var_65);
    var_68 = wp::load(var_58);
    var_67 = wp::div(var_68, var_66);
    // h1 = r.y1 / wp.sqrt(d * d + r.y1 * r.y1)                                               <L 253>
    var_69 = &((var_r).y1);
    var_70 = wp::mul(var_57, var_57);
    var_71 = &((var_r).y1);
    var_72 = &((var_r).y1);
    var_74 = wp::load(var_71);
    var_75 = wp::load(var_72);
    var_73 = wp::mul(var_74, var_75);
    var_76 = wp::add(var_70, var_73);
    var_77 = wp::sqrt(var_76);
    var_79 = wp::load(var_69);
    var_78 = wp::div(var_79, var_77);
    // hv = h0 + u[1] * (h1 - h0)                                                             <L 254>
    var_81 = wp::extract(var_u, var_80);
    var_82 = wp::sub(var_78, var_67);
    var_83 = wp::mul(var_81, var_82);
    var_84 = wp::add(var_67, var_83);
    // hv2 = hv * hv                                                                          <L 255>
    var_85 = wp::mul(var_84, var_84);
    // yv = r.y1                                                                              <L 256>
    var_86 = &((var_r).y1);
    var_88 = wp::load(var_86);
    var_87 = wp::copy(var_88);
    // if hv2 < 1.0 - 1.0e-6:                                                                 <L 257>
    var_91 = wp::sub(var_89, var_90);
    var_92 = (var_85 < var_91);
    if (var_92) {
        // yv = (hv * d) / wp.sqrt(1.0 - hv2)                                                 <L 258>
        var_93 = wp::mul(var_84, var_57);
        var_95 = wp::sub(var_94, var_85);
        var_96 = wp::sqrt(var_95);
        var_97 = wp::div(var_93, var_96);
    }
    var_98 = wp::where(var_92, var_97, var_87);
    // yv = wp.clamp(yv, r.y0, r.y1)                                                          <L 259>
    var_99 = &((var_r).y0);
    var_100 = &((var_r).y1);
    var_102 = wp::load(var_99);
    var_103 = wp::load(var_100);
    var_101 = wp::clamp(var_98, var_102, var_103);
    // return r.o + xu * r.x + yv * r.y + r.z0 * r.z                                          <L 260>
    var_104 = &((var_r).o);
    var_105 = &((var_r).x);
    var_107 = wp::load(var_105);
    var_106 = wp::mul(var_47, var_107);
    var_109 = wp::load(var_104);
    var_108 = wp::add(var_109, var_106);
    var_110 = &((var_r).y);
    var_112 = wp::load(var_110);
    var_111 = wp::mul(var_101, var_112);
    var_113 = wp::add(var_108, var_111);
    var_114 = &((var_r).z0);
    var_115 = &((var_r).z);
    var_117 = wp::load(var_114);
    var_118 = wp::load(var_115);
    var_116 = wp::mul(var_117, var_118);
    var_119 = wp::add(var_113, var_116);
    return var_119;
}


// /work/main/simulator/kernels/lights/rect.py:25
static LightSample_1981fb4b sample_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    bool var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32>* var_3;
    wp::vec_t<3, wp::float32>* var_4;
    wp::float32* var_5;
    wp::float32* var_6;
    SphRect_7f5b29ec var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32* var_12;
    const wp::float32 var_13 = 0.0001;
    bool var_14;
    wp::float32 var_15;
    const wp::int32 var_16 = 0;
    wp::float32 var_17;
    wp::float32* var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::vec_t<3, wp::float32>* var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32> var_24;
    const wp::int32 var_25 = 1;
    wp::float32 var_26;
    wp::float32* var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::vec_t<3, wp::float32>* var_30;
    wp::vec_t<3, wp::float32> var_31;
    wp::vec_t<3, wp::float32> var_32;
    wp::vec_t<3, wp::float32> var_33;
    wp::vec_t<3, wp::float32>* var_34;
    wp::vec_t<3, wp::float32> var_35;
    wp::vec_t<3, wp::float32> var_36;
    LightSample_1981fb4b var_37;
    const wp::int32 var_38 = 0;
    wp::float32 var_39;
    const wp::int32 var_40 = 1;
    wp::float32 var_41;
    wp::vec_t<2, wp::float32> var_42;
    wp::vec_t<3, wp::float32> var_43;
    wp::vec_t<3, wp::float32> var_44;
    wp::float32 var_45;
    const wp::float32 var_46 = 0.0;
    bool var_47;
    wp::vec_t<3, wp::float32> var_48;
    const wp::float32 var_49 = 1.0;
    wp::float32* var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::vec_t<3, wp::float32>* var_53;
    wp::float32 var_54;
    wp::vec_t<3, wp::float32> var_55;
    const wp::float32 var_56 = 0.0;
    bool var_57;
    wp::vec_t<2, wp::float32>* var_58;
    wp::float32* var_59;
    wp::float32 var_60;
    wp::float32 var_61;
    wp::vec_t<2, wp::float32> var_62;
    wp::vec_t<2, wp::float32> var_63;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 26>
    // s = empty_sample()                                                                     <L 27>
    var_0 = empty_sample_0();
    // if behind(l, p):                                                                       <L 28>
    var_1 = behind_0(var_l, var_p);
    if (var_1) {
        // return s  # behind a one-sided emitter                                             <L 29>
        return var_0;
    }
    // c = corner(l)                                                                          <L 30>
    var_2 = corner_0(var_l);
    // sr = sphrect_setup(p, c, l.ex, l.ey, l.width, l.height)                                <L 31>
    var_3 = &((var_l).ex);
    var_4 = &((var_l).ey);
    var_5 = &((var_l).width);
    var_6 = &((var_l).height);
    var_8 = wp::load(var_3);
    var_9 = wp::load(var_4);
    var_10 = wp::load(var_5);
    var_11 = wp::load(var_6);
    var_7 = sphrect_setup_0(var_p, var_2, var_8, var_9, var_10, var_11);
    // if sr.solid_angle <= SPHRECT_MIN_SOLID_ANGLE:                                          <L 32>
    var_12 = &((var_7).solid_angle);
    var_15 = wp::load(var_12);
    var_14 = (var_15 <= var_13);
    if (var_14) {
        // q = c + (u[0] * l.width) * l.ex + (u[1] * l.height) * l.ey                         <L 33>
        var_17 = wp::extract(var_u, var_16);
        var_18 = &((var_l).width);
        var_20 = wp::load(var_18);
        var_19 = wp::mul(var_17, var_20);
        var_21 = &((var_l).ex);
        var_23 = wp::load(var_21);
        var_22 = wp::mul(var_19, var_23);
        var_24 = wp::add(var_2, var_22);
        var_26 = wp::extract(var_u, var_25);
        var_27 = &((var_l).height);
        var_29 = wp::load(var_27);
        var_28 = wp::mul(var_26, var_29);
        var_30 = &((var_l).ey);
        var_32 = wp::load(var_30);
        var_31 = wp::mul(var_28, var_32);
        var_33 = wp::add(var_24, var_31);
        // return area_sample(l, p, n, q, -l.ez)                                              <L 34>
        var_34 = &((var_l).ez);
        var_36 = wp::load(var_34);
        var_35 = wp::neg(var_36);
        var_37 = area_sample_0(var_l, var_p, var_n, var_33, var_35);
        return var_37;
    }
    // q = sphrect_sample(sr, wp.vec2(u[0], u[1]))                                            <L 35>
    var_39 = wp::extract(var_u, var_38);
    var_41 = wp::extract(var_u, var_40);
    var_42 = wp::vec_t<2, wp::float32>(var_39, var_41);
    var_43 = sphrect_sample_0(var_7, var_42);
    // d = q - p                                                                              <L 36>
    var_44 = wp::sub(var_43, var_p);
    // dist = wp.length(d)                                                                    <L 37>
    var_45 = wp::length(var_44);
    // if dist <= 0.0:                                                                        <L 38>
    var_47 = (var_45 <= var_46);
    if (var_47) {
        // return s                                                                           <L 39>
        return var_0;
    }
    // s.wi = d / dist                                                                        <L 40>
    var_48 = wp::div(var_44, var_45);
    var_0.wi = var_48;
    // s.dist = dist                                                                          <L 41>
    var_0.dist = var_45;
    // s.pdf = 1.0 / sr.solid_angle                                                           <L 42>
    var_50 = &((var_7).solid_angle);
    var_52 = wp::load(var_50);
    var_51 = wp::div(var_49, var_52);
    var_0.pdf = var_51;
    // cos_r = wp.dot(s.wi, n)                                                                <L 43>
    var_53 = &((var_0).wi);
    var_55 = wp::load(var_53);
    var_54 = wp::dot(var_55, var_n);
    // if cos_r > 0.0:                                                                        <L 44>
    var_57 = (var_54 > var_56);
    if (var_57) {
        // s.value = l.emission * (cos_r * sr.solid_angle)                                    <L 45>
        var_58 = &((var_l).emission);
        var_59 = &((var_7).solid_angle);
        var_61 = wp::load(var_59);
        var_60 = wp::mul(var_54, var_61);
        var_63 = wp::load(var_58);
        var_62 = wp::mul(var_63, var_60);
        var_0.value = var_62;
    }
    // return s                                                                               <L 46>
    return var_0;
}


// /work/main/simulator/kernels/lights/disk.py:18
static LightSample_1981fb4b sample_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    bool var_0;
    LightSample_1981fb4b var_1;
    const wp::int32 var_2 = 0;
    wp::float32 var_3;
    const wp::int32 var_4 = 1;
    wp::float32 var_5;
    wp::vec_t<2, wp::float32> var_6;
    wp::vec_t<2, wp::float32> var_7;
    wp::float32* var_8;
    wp::vec_t<2, wp::float32> var_9;
    wp::float32 var_10;
    wp::vec_t<3, wp::float32>* var_11;
    const wp::int32 var_12 = 0;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32>* var_14;
    wp::vec_t<3, wp::float32> var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::vec_t<3, wp::float32> var_18;
    const wp::int32 var_19 = 1;
    wp::float32 var_20;
    wp::vec_t<3, wp::float32>* var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32> var_24;
    wp::vec_t<3, wp::float32>* var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::vec_t<3, wp::float32> var_27;
    LightSample_1981fb4b var_28;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 19>
    // if behind(l, p):                                                                       <L 20>
    var_0 = behind_0(var_l, var_p);
    if (var_0) {
        // return empty_sample()  # behind a one-sided emitter                                <L 21>
        var_1 = empty_sample_0();
        return var_1;
    }
    // dp = sample_concentric_disk(wp.vec2(u[0], u[1])) * l.radius                            <L 22>
    var_3 = wp::extract(var_u, var_2);
    var_5 = wp::extract(var_u, var_4);
    var_6 = wp::vec_t<2, wp::float32>(var_3, var_5);
    var_7 = sample_concentric_disk_0(var_6);
    var_8 = &((var_l).radius);
    var_10 = wp::load(var_8);
    var_9 = wp::mul(var_7, var_10);
    // return area_sample(l, p, n, l.position + dp[0] * l.ex + dp[1] * l.ey, -l.ez)           <L 23>
    var_11 = &((var_l).position);
    var_13 = wp::extract(var_9, var_12);
    var_14 = &((var_l).ex);
    var_16 = wp::load(var_14);
    var_15 = wp::mul(var_13, var_16);
    var_18 = wp::load(var_11);
    var_17 = wp::add(var_18, var_15);
    var_20 = wp::extract(var_9, var_19);
    var_21 = &((var_l).ey);
    var_23 = wp::load(var_21);
    var_22 = wp::mul(var_20, var_23);
    var_24 = wp::add(var_17, var_22);
    var_25 = &((var_l).ez);
    var_27 = wp::load(var_25);
    var_26 = wp::neg(var_27);
    var_28 = area_sample_0(var_l, var_p, var_n, var_24, var_26);
    return var_28;
}


// /work/main/simulator/kernels/lights/distant.py:19
static LightSample_1981fb4b sample_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    const wp::float32 var_1 = 1e+30;
    wp::float32* var_2;
    const wp::float32 var_3 = 0.0;
    bool var_4;
    wp::float32 var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32>* var_9;
    wp::float32 var_10;
    wp::vec_t<3, wp::float32> var_11;
    const wp::float32 var_12 = 0.0;
    bool var_13;
    wp::vec_t<2, wp::float32>* var_14;
    wp::vec_t<2, wp::float32> var_15;
    wp::vec_t<2, wp::float32> var_16;
    const wp::int32 var_17 = 0;
    wp::float32 var_18;
    const wp::int32 var_19 = 1;
    wp::float32 var_20;
    wp::vec_t<2, wp::float32> var_21;
    wp::float32* var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::float32 var_24;
    wp::vec_t<3, wp::float32>* var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::vec_t<3, wp::float32> var_27;
    wp::float32* var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::vec_t<3, wp::float32>* var_31;
    wp::float32 var_32;
    wp::vec_t<3, wp::float32> var_33;
    const wp::float32 var_34 = 0.0;
    bool var_35;
    wp::vec_t<2, wp::float32>* var_36;
    wp::float32* var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    wp::vec_t<2, wp::float32> var_40;
    wp::vec_t<2, wp::float32> var_41;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 20>
    // s = empty_sample()                                                                     <L 21>
    var_0 = empty_sample_0();
    // s.dist = RAY_INF                                                                       <L 22>
    var_0.dist = var_1;
    // if l.one_minus_cos <= 0.0:                                                             <L 23>
    var_2 = &((var_l).one_minus_cos);
    var_5 = wp::load(var_2);
    var_4 = (var_5 <= var_3);
    if (var_4) {
        // s.wi = l.ez                                                                        <L 24>
        var_6 = &((var_l).ez);
        var_8 = wp::load(var_6);
        var_7 = wp::copy(var_8);
        var_0.wi = var_7;
        // cos_r = wp.dot(l.ez, n)                                                            <L 25>
        var_9 = &((var_l).ez);
        var_11 = wp::load(var_9);
        var_10 = wp::dot(var_11, var_n);
        // if cos_r > 0.0:                                                                    <L 26>
        var_13 = (var_10 > var_12);
        if (var_13) {
            // s.value = l.emission * cos_r  # E = E⊥·cosξ                                    <L 27>
            var_14 = &((var_l).emission);
            var_16 = wp::load(var_14);
            var_15 = wp::mul(var_16, var_10);
            var_0.value = var_15;
        }
        // return s                                                                           <L 28>
        return var_0;
    }
    // s.wi = to_world(sample_uniform_cone(wp.vec2(u[0], u[1]), l.one_minus_cos), l.ez)       <L 29>
    var_18 = wp::extract(var_u, var_17);
    var_20 = wp::extract(var_u, var_19);
    var_21 = wp::vec_t<2, wp::float32>(var_18, var_20);
    var_22 = &((var_l).one_minus_cos);
    var_24 = wp::load(var_22);
    var_23 = sample_uniform_cone_0(var_21, var_24);
    var_25 = &((var_l).ez);
    var_27 = wp::load(var_25);
    var_26 = to_world_0(var_23, var_27);
    var_0.wi = var_26;
    // s.pdf = pdf_uniform_cone(l.one_minus_cos)                                              <L 30>
    var_28 = &((var_l).one_minus_cos);
    var_30 = wp::load(var_28);
    var_29 = pdf_uniform_cone_0(var_30);
    var_0.pdf = var_29;
    // cos_r = wp.dot(s.wi, n)                                                                <L 31>
    var_31 = &((var_0).wi);
    var_33 = wp::load(var_31);
    var_32 = wp::dot(var_33, var_n);
    // if cos_r > 0.0:                                                                        <L 32>
    var_35 = (var_32 > var_34);
    if (var_35) {
        // s.value = l.emission * (cos_r / s.pdf)                                             <L 33>
        var_36 = &((var_l).emission);
        var_37 = &((var_0).pdf);
        var_39 = wp::load(var_37);
        var_38 = wp::div(var_32, var_39);
        var_41 = wp::load(var_36);
        var_40 = wp::mul(var_41, var_38);
        var_0.value = var_40;
    }
    // return s                                                                               <L 34>
    return var_0;
}


// /work/main/simulator/kernels/lights/dome.py:78
static bool portal_guides_0(
    PortalRec_445c1fd2 var_pt,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32>* var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32> var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    const bool var_8 = false;
    wp::float32* var_9;
    wp::vec_t<3, wp::float32>* var_10;
    wp::vec_t<3, wp::float32> var_11;
    wp::float32 var_12;
    wp::vec_t<3, wp::float32> var_13;
    wp::float32* var_14;
    wp::vec_t<3, wp::float32>* var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::float32 var_17;
    wp::vec_t<3, wp::float32> var_18;
    wp::vec_t<3, wp::float32>* var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    const wp::float32 var_32 = 0.0;
    bool var_33;
    //---------
    // forward
    // def portal_guides(pt: PortalRec, p: wp.vec3, n: wp.vec3) -> bool:                      <L 79>
    // if wp.dot(p - pt.corner, pt.ez) >= 0.0:                                                <L 83>
    var_0 = &((var_pt).corner);
    var_2 = wp::load(var_0);
    var_1 = wp::sub(var_p, var_2);
    var_3 = &((var_pt).ez);
    var_5 = wp::load(var_3);
    var_4 = wp::dot(var_1, var_5);
    var_7 = (var_4 >= var_6);
    if (var_7) {
        // return False                                                                       <L 84>
        return var_8;
    }
    // a = pt.width * pt.ex                                                                   <L 85>
    var_9 = &((var_pt).width);
    var_10 = &((var_pt).ex);
    var_12 = wp::load(var_9);
    var_13 = wp::load(var_10);
    var_11 = wp::mul(var_12, var_13);
    // b = pt.height * pt.ey                                                                  <L 86>
    var_14 = &((var_pt).height);
    var_15 = &((var_pt).ey);
    var_17 = wp::load(var_14);
    var_18 = wp::load(var_15);
    var_16 = wp::mul(var_17, var_18);
    // h0 = wp.dot(pt.corner - p, n)                                                          <L 87>
    var_19 = &((var_pt).corner);
    var_21 = wp::load(var_19);
    var_20 = wp::sub(var_21, var_p);
    var_22 = wp::dot(var_20, var_n);
    // h1 = h0 + wp.dot(a, n)                                                                 <L 88>
    var_23 = wp::dot(var_11, var_n);
    var_24 = wp::add(var_22, var_23);
    // h2 = h1 + wp.dot(b, n)                                                                 <L 89>
    var_25 = wp::dot(var_16, var_n);
    var_26 = wp::add(var_24, var_25);
    // h3 = h0 + wp.dot(b, n)                                                                 <L 90>
    var_27 = wp::dot(var_16, var_n);
    var_28 = wp::add(var_22, var_27);
    // return wp.max(wp.max(h0, h1), wp.max(h2, h3)) > 0.0                                    <L 91>
    var_29 = wp::max(var_22, var_24);
    var_30 = wp::max(var_26, var_28);
    var_31 = wp::max(var_29, var_30);
    var_33 = (var_31 > var_32);
    return var_33;
}


// /work/main/simulator/kernels/closed_forms.py:79
static wp::float64 _edge_term_0(
    wp::vec_t<3, wp::float64> var_a,
    wp::vec_t<3, wp::float64> var_b,
    wp::vec_t<3, wp::float64> var_n)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float64> var_0;
    wp::float64 var_1;
    wp::float64 var_2;
    bool var_3;
    wp::float64 var_4;
    wp::float64 var_5;
    wp::float64 var_6;
    wp::float64 var_7;
    wp::float64 var_8;
    wp::float64 var_9;
    //---------
    // forward
    // def _edge_term(a: wp.vec3d, b: wp.vec3d, n: wp.vec3d) -> wp.float64:                   <L 80>
    // c = wp.cross(a, b)                                                                     <L 84>
    var_0 = wp::cross(var_a, var_b);
    // s = wp.length(c)                                                                       <L 85>
    var_1 = wp::length(var_0);
    // if s <= wp.float64(0.0):                                                               <L 86>
    var_2 = 0.0;
    var_3 = (var_1 <= var_2);
    if (var_3) {
        // return wp.float64(0.0)                                                             <L 87>
        var_4 = 0.0;
        return var_4;
    }
    // return wp.atan2(s, wp.dot(a, b)) * wp.dot(n, c) / s                                    <L 88>
    var_5 = wp::dot(var_a, var_b);
    var_6 = wp::atan2(var_1, var_5);
    var_7 = wp::dot(var_n, var_0);
    var_8 = wp::mul(var_6, var_7);
    var_9 = wp::div(var_8, var_1);
    return var_9;
}


// /work/main/simulator/kernels/closed_forms.py:91
static wp::float32 polygon_irradiance4_0(
    wp::vec_t<3, wp::float32> var_v0,
    wp::vec_t<3, wp::float32> var_v1,
    wp::vec_t<3, wp::float32> var_v2,
    wp::vec_t<3, wp::float32> var_v3,
    wp::int32 var_nv,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float64> var_0;
    wp::vec_t<3, wp::float64> var_1;
    wp::vec_t<3, wp::float64> var_2;
    wp::vec_t<3, wp::float64> var_3;
    wp::vec_t<3, wp::float64> var_4;
    wp::vec_t<3, wp::float64> var_5;
    wp::vec_t<3, wp::float64> var_6;
    wp::vec_t<3, wp::float64> var_7;
    wp::vec_t<3, wp::float64> var_8;
    wp::vec_t<3, wp::float64> var_9;
    const wp::int32 var_10 = 3;
    bool var_11;
    wp::vec_t<3, wp::float64> var_12;
    wp::vec_t<3, wp::float64> var_13;
    wp::float64 var_14;
    wp::float64 var_15;
    wp::vec_t<3, wp::float64> var_16;
    const wp::int32 var_17 = 0;
    wp::int32 var_18;
    wp::vec_t<3, wp::float64> var_19;
    const wp::int32 var_20 = 0;
    wp::int32 var_21;
    const wp::int32 var_22 = 0;
    const bool var_23 = true;
    bool var_24;
    const bool var_25 = false;
    bool var_26;
    wp::vec_t<3, wp::float64> var_27;
    wp::vec_t<3, wp::float64> var_28;
    const wp::int32 var_29 = 1;
    bool var_30;
    wp::vec_t<3, wp::float64> var_31;
    wp::vec_t<3, wp::float64> var_32;
    const wp::int32 var_33 = 2;
    bool var_34;
    wp::vec_t<3, wp::float64> var_35;
    wp::vec_t<3, wp::float64> var_36;
    const wp::int32 var_37 = 3;
    bool var_38;
    wp::vec_t<3, wp::float64> var_39;
    wp::vec_t<3, wp::float64> var_40;
    const wp::int32 var_41 = 3;
    bool var_42;
    wp::vec_t<3, wp::float64> var_43;
    wp::vec_t<3, wp::float64> var_44;
    wp::vec_t<3, wp::float64> var_45;
    wp::vec_t<3, wp::float64> var_46;
    wp::vec_t<3, wp::float64> var_47;
    wp::vec_t<3, wp::float64> var_48;
    wp::vec_t<3, wp::float64> var_49;
    wp::vec_t<3, wp::float64> var_50;
    wp::float64 var_51;
    wp::float64 var_52;
    bool var_53;
    bool var_54;
    bool var_55;
    wp::vec_t<3, wp::float64> var_56;
    wp::vec_t<3, wp::float64> var_57;
    wp::float64 var_58;
    wp::float64 var_59;
    bool var_60;
    bool var_61;
    bool var_62;
    wp::vec_t<3, wp::float64> var_63;
    wp::float64 var_64;
    wp::float64 var_65;
    wp::vec_t<3, wp::float64> var_66;
    wp::vec_t<3, wp::float64> var_67;
    wp::vec_t<3, wp::float64> var_68;
    wp::vec_t<3, wp::float64> var_69;
    wp::float64 var_70;
    wp::float64 var_71;
    wp::vec_t<3, wp::float64> var_72;
    const wp::int32 var_73 = 1;
    bool var_74;
    bool var_75;
    bool var_76;
    wp::vec_t<3, wp::float64> var_77;
    wp::float64 var_78;
    wp::float64 var_79;
    wp::vec_t<3, wp::float64> var_80;
    wp::vec_t<3, wp::float64> var_81;
    wp::vec_t<3, wp::float64> var_82;
    wp::vec_t<3, wp::float64> var_83;
    wp::float64 var_84;
    wp::float64 var_85;
    const wp::int32 var_86 = 0;
    bool var_87;
    wp::vec_t<3, wp::float64> var_88;
    wp::vec_t<3, wp::float64> var_89;
    wp::float64 var_90;
    wp::float64 var_91;
    const wp::int32 var_92 = 0;
    wp::vec_t<3, wp::float64> var_93;
    const wp::int32 var_94 = 1;
    wp::float64 var_95;
    wp::int32 var_96;
    wp::vec_t<3, wp::float64> var_97;
    wp::int32 var_98;
    wp::float64 var_99;
    wp::int32 var_100;
    wp::vec_t<3, wp::float64> var_101;
    wp::int32 var_102;
    wp::float64 var_103;
    wp::vec_t<3, wp::float64> var_104;
    wp::int32 var_105;
    wp::vec_t<3, wp::float64> var_106;
    wp::int32 var_107;
    wp::vec_t<3, wp::float64> var_108;
    wp::float64 var_109;
    wp::vec_t<3, wp::float64> var_110;
    wp::int32 var_111;
    wp::vec_t<3, wp::float64> var_112;
    wp::int32 var_113;
    wp::float64 var_114;
    wp::vec_t<3, wp::float64> var_115;
    wp::int32 var_116;
    wp::vec_t<3, wp::float64> var_117;
    wp::int32 var_118;
    const wp::int32 var_119 = 1;
    const bool var_120 = true;
    bool var_121;
    const bool var_122 = false;
    bool var_123;
    wp::vec_t<3, wp::float64> var_124;
    wp::vec_t<3, wp::float64> var_125;
    const wp::int32 var_126 = 1;
    bool var_127;
    wp::vec_t<3, wp::float64> var_128;
    wp::vec_t<3, wp::float64> var_129;
    const wp::int32 var_130 = 2;
    bool var_131;
    wp::vec_t<3, wp::float64> var_132;
    wp::vec_t<3, wp::float64> var_133;
    const wp::int32 var_134 = 3;
    bool var_135;
    wp::vec_t<3, wp::float64> var_136;
    wp::vec_t<3, wp::float64> var_137;
    const wp::int32 var_138 = 3;
    bool var_139;
    wp::vec_t<3, wp::float64> var_140;
    wp::vec_t<3, wp::float64> var_141;
    wp::vec_t<3, wp::float64> var_142;
    wp::vec_t<3, wp::float64> var_143;
    wp::vec_t<3, wp::float64> var_144;
    wp::vec_t<3, wp::float64> var_145;
    wp::vec_t<3, wp::float64> var_146;
    wp::vec_t<3, wp::float64> var_147;
    wp::float64 var_148;
    wp::float64 var_149;
    bool var_150;
    bool var_151;
    bool var_152;
    wp::vec_t<3, wp::float64> var_153;
    wp::vec_t<3, wp::float64> var_154;
    wp::float64 var_155;
    wp::float64 var_156;
    bool var_157;
    bool var_158;
    bool var_159;
    wp::vec_t<3, wp::float64> var_160;
    wp::float64 var_161;
    wp::float64 var_162;
    wp::vec_t<3, wp::float64> var_163;
    wp::vec_t<3, wp::float64> var_164;
    wp::vec_t<3, wp::float64> var_165;
    wp::vec_t<3, wp::float64> var_166;
    wp::float64 var_167;
    wp::float64 var_168;
    wp::vec_t<3, wp::float64> var_169;
    const wp::int32 var_170 = 1;
    bool var_171;
    bool var_172;
    bool var_173;
    wp::vec_t<3, wp::float64> var_174;
    wp::float64 var_175;
    wp::float64 var_176;
    wp::vec_t<3, wp::float64> var_177;
    wp::vec_t<3, wp::float64> var_178;
    wp::vec_t<3, wp::float64> var_179;
    wp::vec_t<3, wp::float64> var_180;
    wp::float64 var_181;
    wp::float64 var_182;
    const wp::int32 var_183 = 0;
    bool var_184;
    wp::vec_t<3, wp::float64> var_185;
    wp::vec_t<3, wp::float64> var_186;
    wp::float64 var_187;
    wp::float64 var_188;
    const wp::int32 var_189 = 0;
    wp::vec_t<3, wp::float64> var_190;
    const wp::int32 var_191 = 1;
    wp::float64 var_192;
    wp::int32 var_193;
    wp::vec_t<3, wp::float64> var_194;
    wp::int32 var_195;
    wp::float64 var_196;
    wp::int32 var_197;
    wp::vec_t<3, wp::float64> var_198;
    wp::int32 var_199;
    wp::vec_t<3, wp::float64> var_200;
    wp::float64 var_201;
    wp::vec_t<3, wp::float64> var_202;
    wp::int32 var_203;
    wp::vec_t<3, wp::float64> var_204;
    wp::int32 var_205;
    wp::vec_t<3, wp::float64> var_206;
    wp::float64 var_207;
    wp::vec_t<3, wp::float64> var_208;
    wp::int32 var_209;
    wp::vec_t<3, wp::float64> var_210;
    wp::int32 var_211;
    wp::vec_t<3, wp::float64> var_212;
    wp::float64 var_213;
    wp::vec_t<3, wp::float64> var_214;
    wp::int32 var_215;
    wp::vec_t<3, wp::float64> var_216;
    wp::int32 var_217;
    wp::vec_t<3, wp::float64> var_218;
    wp::vec_t<3, wp::float64> var_219;
    wp::float64 var_220;
    wp::float64 var_221;
    wp::vec_t<3, wp::float64> var_222;
    const wp::int32 var_223 = 2;
    const bool var_224 = true;
    bool var_225;
    const bool var_226 = false;
    bool var_227;
    wp::vec_t<3, wp::float64> var_228;
    wp::vec_t<3, wp::float64> var_229;
    const wp::int32 var_230 = 1;
    bool var_231;
    wp::vec_t<3, wp::float64> var_232;
    wp::vec_t<3, wp::float64> var_233;
    const wp::int32 var_234 = 2;
    bool var_235;
    wp::vec_t<3, wp::float64> var_236;
    wp::vec_t<3, wp::float64> var_237;
    const wp::int32 var_238 = 3;
    bool var_239;
    wp::vec_t<3, wp::float64> var_240;
    wp::vec_t<3, wp::float64> var_241;
    const wp::int32 var_242 = 3;
    bool var_243;
    wp::vec_t<3, wp::float64> var_244;
    wp::vec_t<3, wp::float64> var_245;
    wp::vec_t<3, wp::float64> var_246;
    wp::vec_t<3, wp::float64> var_247;
    wp::vec_t<3, wp::float64> var_248;
    wp::vec_t<3, wp::float64> var_249;
    wp::vec_t<3, wp::float64> var_250;
    wp::vec_t<3, wp::float64> var_251;
    wp::float64 var_252;
    wp::float64 var_253;
    bool var_254;
    bool var_255;
    bool var_256;
    wp::vec_t<3, wp::float64> var_257;
    wp::vec_t<3, wp::float64> var_258;
    wp::float64 var_259;
    wp::float64 var_260;
    bool var_261;
    bool var_262;
    bool var_263;
    wp::vec_t<3, wp::float64> var_264;
    wp::float64 var_265;
    wp::float64 var_266;
    wp::vec_t<3, wp::float64> var_267;
    wp::vec_t<3, wp::float64> var_268;
    wp::vec_t<3, wp::float64> var_269;
    wp::vec_t<3, wp::float64> var_270;
    wp::float64 var_271;
    wp::float64 var_272;
    wp::vec_t<3, wp::float64> var_273;
    const wp::int32 var_274 = 1;
    bool var_275;
    bool var_276;
    bool var_277;
    wp::vec_t<3, wp::float64> var_278;
    wp::float64 var_279;
    wp::float64 var_280;
    wp::vec_t<3, wp::float64> var_281;
    wp::vec_t<3, wp::float64> var_282;
    wp::vec_t<3, wp::float64> var_283;
    wp::vec_t<3, wp::float64> var_284;
    wp::float64 var_285;
    wp::float64 var_286;
    const wp::int32 var_287 = 0;
    bool var_288;
    wp::vec_t<3, wp::float64> var_289;
    wp::vec_t<3, wp::float64> var_290;
    wp::float64 var_291;
    wp::float64 var_292;
    const wp::int32 var_293 = 0;
    wp::vec_t<3, wp::float64> var_294;
    const wp::int32 var_295 = 1;
    wp::float64 var_296;
    wp::int32 var_297;
    wp::vec_t<3, wp::float64> var_298;
    wp::int32 var_299;
    wp::float64 var_300;
    wp::int32 var_301;
    wp::vec_t<3, wp::float64> var_302;
    wp::int32 var_303;
    wp::vec_t<3, wp::float64> var_304;
    wp::float64 var_305;
    wp::vec_t<3, wp::float64> var_306;
    wp::int32 var_307;
    wp::vec_t<3, wp::float64> var_308;
    wp::int32 var_309;
    wp::vec_t<3, wp::float64> var_310;
    wp::float64 var_311;
    wp::vec_t<3, wp::float64> var_312;
    wp::int32 var_313;
    wp::vec_t<3, wp::float64> var_314;
    wp::int32 var_315;
    wp::vec_t<3, wp::float64> var_316;
    wp::float64 var_317;
    wp::vec_t<3, wp::float64> var_318;
    wp::int32 var_319;
    wp::vec_t<3, wp::float64> var_320;
    wp::int32 var_321;
    wp::vec_t<3, wp::float64> var_322;
    wp::vec_t<3, wp::float64> var_323;
    wp::float64 var_324;
    wp::float64 var_325;
    wp::vec_t<3, wp::float64> var_326;
    const wp::int32 var_327 = 3;
    const bool var_328 = true;
    bool var_329;
    const bool var_330 = false;
    bool var_331;
    wp::vec_t<3, wp::float64> var_332;
    wp::vec_t<3, wp::float64> var_333;
    const wp::int32 var_334 = 1;
    bool var_335;
    wp::vec_t<3, wp::float64> var_336;
    wp::vec_t<3, wp::float64> var_337;
    const wp::int32 var_338 = 2;
    bool var_339;
    wp::vec_t<3, wp::float64> var_340;
    wp::vec_t<3, wp::float64> var_341;
    const wp::int32 var_342 = 3;
    bool var_343;
    wp::vec_t<3, wp::float64> var_344;
    wp::vec_t<3, wp::float64> var_345;
    const wp::int32 var_346 = 3;
    bool var_347;
    wp::vec_t<3, wp::float64> var_348;
    wp::vec_t<3, wp::float64> var_349;
    wp::vec_t<3, wp::float64> var_350;
    wp::vec_t<3, wp::float64> var_351;
    wp::vec_t<3, wp::float64> var_352;
    wp::vec_t<3, wp::float64> var_353;
    wp::vec_t<3, wp::float64> var_354;
    wp::vec_t<3, wp::float64> var_355;
    wp::float64 var_356;
    wp::float64 var_357;
    bool var_358;
    bool var_359;
    bool var_360;
    wp::vec_t<3, wp::float64> var_361;
    wp::vec_t<3, wp::float64> var_362;
    wp::float64 var_363;
    wp::float64 var_364;
    bool var_365;
    bool var_366;
    bool var_367;
    wp::vec_t<3, wp::float64> var_368;
    wp::float64 var_369;
    wp::float64 var_370;
    wp::vec_t<3, wp::float64> var_371;
    wp::vec_t<3, wp::float64> var_372;
    wp::vec_t<3, wp::float64> var_373;
    wp::vec_t<3, wp::float64> var_374;
    wp::float64 var_375;
    wp::float64 var_376;
    wp::vec_t<3, wp::float64> var_377;
    const wp::int32 var_378 = 1;
    bool var_379;
    bool var_380;
    bool var_381;
    wp::vec_t<3, wp::float64> var_382;
    wp::float64 var_383;
    wp::float64 var_384;
    wp::vec_t<3, wp::float64> var_385;
    wp::vec_t<3, wp::float64> var_386;
    wp::vec_t<3, wp::float64> var_387;
    wp::vec_t<3, wp::float64> var_388;
    wp::float64 var_389;
    wp::float64 var_390;
    const wp::int32 var_391 = 0;
    bool var_392;
    wp::vec_t<3, wp::float64> var_393;
    wp::vec_t<3, wp::float64> var_394;
    wp::float64 var_395;
    wp::float64 var_396;
    const wp::int32 var_397 = 0;
    wp::vec_t<3, wp::float64> var_398;
    const wp::int32 var_399 = 1;
    wp::float64 var_400;
    wp::int32 var_401;
    wp::vec_t<3, wp::float64> var_402;
    wp::int32 var_403;
    wp::float64 var_404;
    wp::int32 var_405;
    wp::vec_t<3, wp::float64> var_406;
    wp::int32 var_407;
    wp::vec_t<3, wp::float64> var_408;
    wp::float64 var_409;
    wp::vec_t<3, wp::float64> var_410;
    wp::int32 var_411;
    wp::vec_t<3, wp::float64> var_412;
    wp::int32 var_413;
    wp::vec_t<3, wp::float64> var_414;
    wp::float64 var_415;
    wp::vec_t<3, wp::float64> var_416;
    wp::int32 var_417;
    wp::vec_t<3, wp::float64> var_418;
    wp::int32 var_419;
    wp::vec_t<3, wp::float64> var_420;
    wp::float64 var_421;
    wp::vec_t<3, wp::float64> var_422;
    wp::int32 var_423;
    wp::vec_t<3, wp::float64> var_424;
    wp::int32 var_425;
    wp::vec_t<3, wp::float64> var_426;
    wp::vec_t<3, wp::float64> var_427;
    wp::float64 var_428;
    wp::float64 var_429;
    wp::vec_t<3, wp::float64> var_430;
    bool var_431;
    const wp::int32 var_432 = 0;
    bool var_433;
    const wp::int32 var_434 = 0;
    bool var_435;
    wp::vec_t<3, wp::float64> var_436;
    wp::vec_t<3, wp::float64> var_437;
    wp::float64 var_438;
    wp::float64 var_439;
    wp::float64 var_440;
    wp::float64 var_441;
    wp::float64 var_442;
    wp::float64 var_443;
    wp::float32 var_444;
    //---------
    // forward
    // def polygon_irradiance4(v0: wp.vec3, v1: wp.vec3, v2: wp.vec3, v3: wp.vec3, nv: int, p: wp.vec3, n: wp.vec3) -> float:       <L 92>
    // pd = wp.vec3d(p)                                                                       <L 97>
    var_0 = wp::vec_t<3, wp::float64>(var_p);
    // nd = wp.vec3d(n)                                                                       <L 98>
    var_1 = wp::vec_t<3, wp::float64>(var_n);
    // r0 = wp.vec3d(v0) - pd                                                                 <L 99>
    var_2 = wp::vec_t<3, wp::float64>(var_v0);
    var_3 = wp::sub(var_2, var_0);
    // r1 = wp.vec3d(v1) - pd                                                                 <L 100>
    var_4 = wp::vec_t<3, wp::float64>(var_v1);
    var_5 = wp::sub(var_4, var_0);
    // r2 = wp.vec3d(v2) - pd                                                                 <L 101>
    var_6 = wp::vec_t<3, wp::float64>(var_v2);
    var_7 = wp::sub(var_6, var_0);
    // r3 = wp.vec3d(v3) - pd                                                                 <L 102>
    var_8 = wp::vec_t<3, wp::float64>(var_v3);
    var_9 = wp::sub(var_8, var_0);
    // if nv == 3:                                                                            <L 103>
    var_11 = (var_nv == var_10);
    if (var_11) {
        // r3 = r0                                                                            <L 104>
        var_12 = wp::copy(var_3);
    }
    var_13 = wp::where(var_11, var_12, var_9);
    // f0 = wp.float64(0.0)                                                                   <L 105>
    var_14 = 0.0;
    // total = wp.float64(0.0)                                                                <L 106>
    var_15 = 0.0;
    // exit_pt = wp.vec3d(f0, f0, f0)                                                         <L 109>
    var_16 = wp::vec_t<3, wp::float64>(var_14, var_14, var_14);
    // have_exit = int(0)                                                                     <L 110>
    var_18 = wp::int(var_17);
    // first_enter = wp.vec3d(f0, f0, f0)                                                     <L 111>
    var_19 = wp::vec_t<3, wp::float64>(var_14, var_14, var_14);
    // pending_enter = int(0)                                                                 <L 112>
    var_21 = wp::int(var_20);
    // for k in range(4):                                                                     <L 113>
    // if k >= nv:                                                                            <L 114>
    var_24 = (var_22 >= var_nv);
    if (var_24) {
        // continue                                                                           <L 115>
    }
    var_26 = wp::where(var_24, var_25, var_23);
    // a = r0                                                                                 <L 116>
    if (var_26) {
        var_27 = wp::copy(var_3);
        // b = r1                                                                             <L 117>
        var_28 = wp::copy(var_5);
        // if k == 1:                                                                         <L 118>
        var_30 = (var_22 == var_29);
        if (var_30) {
            // a = r1                                                                         <L 119>
            var_31 = wp::copy(var_5);
            // b = r2                                                                         <L 120>
            var_32 = wp::copy(var_7);
        }
        if (!var_30) {
            // elif k == 2:                                                                   <L 121>
            var_34 = (var_22 == var_33);
            if (var_34) {
                // a = r2                                                                     <L 122>
                var_35 = wp::copy(var_7);
                // b = r3                                                                     <L 123>
                var_36 = wp::copy(var_13);
                // if nv == 3:                                                                <L 124>
                var_38 = (var_nv == var_37);
                if (var_38) {
                    // b = r0                                                                 <L 125>
                    var_39 = wp::copy(var_3);
                }
                var_40 = wp::where(var_38, var_39, var_36);
            }
            if (!var_34) {
                // elif k == 3:                                                               <L 126>
                var_42 = (var_22 == var_41);
                if (var_42) {
                    // a = r3                                                                 <L 127>
                    var_43 = wp::copy(var_13);
                    // b = r0                                                                 <L 128>
                    var_44 = wp::copy(var_3);
                }
                var_45 = wp::where(var_42, var_43, var_27);
                var_46 = wp::where(var_42, var_44, var_28);
            }
            var_47 = wp::where(var_34, var_35, var_45);
            var_48 = wp::where(var_34, var_40, var_46);
        }
        var_49 = wp::where(var_30, var_31, var_47);
        var_50 = wp::where(var_30, var_32, var_48);
        // ha = wp.dot(a, nd)                                                                 <L 129>
        var_51 = wp::dot(var_49, var_1);
        // hb = wp.dot(b, nd)                                                                 <L 130>
        var_52 = wp::dot(var_50, var_1);
        // if ha > f0 and hb > f0:                                                            <L 131>
        var_54 = (var_51 > var_14);
        var_53 = var_54;
        if (var_53) {
            var_55 = (var_52 > var_14);
            var_53 = var_53 && var_55;
        }
        if (var_53) {
            // total += _edge_term(wp.normalize(a), wp.normalize(b), nd)                      <L 132>
            var_56 = wp::normalize(var_49);
            var_57 = wp::normalize(var_50);
            var_58 = _edge_term_0(var_56, var_57, var_1);
            var_59 = wp::add(var_15, var_58);
        }
        if (!var_53) {
            // elif ha > f0 and hb <= f0:                                                     <L 133>
            var_61 = (var_51 > var_14);
            var_60 = var_61;
            if (var_60) {
                var_62 = (var_52 <= var_14);
                var_60 = var_60 && var_62;
            }
            if (var_60) {
                // x = a + (b - a) * (ha / (ha - hb))  # leaves the hemisphere                <L 134>
                var_63 = wp::sub(var_50, var_49);
                var_64 = wp::sub(var_51, var_52);
                var_65 = wp::div(var_51, var_64);
                var_66 = wp::mul(var_63, var_65);
                var_67 = wp::add(var_49, var_66);
                // total += _edge_term(wp.normalize(a), wp.normalize(x), nd)                  <L 135>
                var_68 = wp::normalize(var_49);
                var_69 = wp::normalize(var_67);
                var_70 = _edge_term_0(var_68, var_69, var_1);
                var_71 = wp::add(var_15, var_70);
                // exit_pt = x                                                                <L 136>
                var_72 = wp::copy(var_67);
                // have_exit = 1                                                              <L 137>
            }
            if (!var_60) {
                // elif ha <= f0 and hb > f0:                                                 <L 138>
                var_75 = (var_51 <= var_14);
                var_74 = var_75;
                if (var_74) {
                    var_76 = (var_52 > var_14);
                    var_74 = var_74 && var_76;
                }
                if (var_74) {
                    // x = a + (b - a) * (ha / (ha - hb))  # enters                           <L 139>
                    var_77 = wp::sub(var_50, var_49);
                    var_78 = wp::sub(var_51, var_52);
                    var_79 = wp::div(var_51, var_78);
                    var_80 = wp::mul(var_77, var_79);
                    var_81 = wp::add(var_49, var_80);
                    // total += _edge_term(wp.normalize(x), wp.normalize(b), nd)              <L 140>
                    var_82 = wp::normalize(var_81);
                    var_83 = wp::normalize(var_50);
                    var_84 = _edge_term_0(var_82, var_83, var_1);
                    var_85 = wp::add(var_15, var_84);
                    // if have_exit != 0:                                                     <L 141>
                    var_87 = (var_18 != var_86);
                    if (var_87) {
                        // total += _edge_term(wp.normalize(exit_pt), wp.normalize(x), nd)       <L 142>
                        var_88 = wp::normalize(var_16);
                        var_89 = wp::normalize(var_81);
                        var_90 = _edge_term_0(var_88, var_89, var_1);
                        var_91 = wp::add(var_85, var_90);
                        // have_exit = 0                                                      <L 143>
                    }
                    if (!var_87) {
                        // first_enter = x                                                    <L 145>
                        var_93 = wp::copy(var_81);
                        // pending_enter = 1                                                  <L 146>
                    }
                    var_95 = wp::where(var_87, var_91, var_85);
                    var_96 = wp::where(var_87, var_92, var_18);
                    var_97 = wp::where(var_87, var_19, var_93);
                    var_98 = wp::where(var_87, var_21, var_94);
                }
                var_99 = wp::where(var_74, var_95, var_15);
                var_100 = wp::where(var_74, var_96, var_18);
                var_101 = wp::where(var_74, var_97, var_19);
                var_102 = wp::where(var_74, var_98, var_21);
            }
            var_103 = wp::where(var_60, var_71, var_99);
            var_104 = wp::where(var_60, var_72, var_16);
            var_105 = wp::where(var_60, var_73, var_100);
            var_106 = wp::where(var_60, var_19, var_101);
            var_107 = wp::where(var_60, var_21, var_102);
            var_108 = wp::where(var_60, var_67, var_81);
        }
        var_109 = wp::where(var_53, var_59, var_103);
        var_110 = wp::where(var_53, var_16, var_104);
        var_111 = wp::where(var_53, var_18, var_105);
        var_112 = wp::where(var_53, var_19, var_106);
        var_113 = wp::where(var_53, var_21, var_107);
    }
    var_114 = wp::where(var_26, var_109, var_15);
    var_115 = wp::where(var_26, var_110, var_16);
    var_116 = wp::where(var_26, var_111, var_18);
    var_117 = wp::where(var_26, var_112, var_19);
    var_118 = wp::where(var_26, var_113, var_21);
    // if k >= nv:                                                                            <L 114>
    var_121 = (var_119 >= var_nv);
    if (var_121) {
        // continue                                                                           <L 115>
    }
    var_123 = wp::where(var_121, var_122, var_120);
    // a = r0                                                                                 <L 116>
    if (var_123) {
        var_124 = wp::copy(var_3);
        // b = r1                                                                             <L 117>
        var_125 = wp::copy(var_5);
        // if k == 1:                                                                         <L 118>
        var_127 = (var_119 == var_126);
        if (var_127) {
            // a = r1                                                                         <L 119>
            var_128 = wp::copy(var_5);
            // b = r2                                                                         <L 120>
            var_129 = wp::copy(var_7);
        }
        if (!var_127) {
            // elif k == 2:                                                                   <L 121>
            var_131 = (var_119 == var_130);
            if (var_131) {
                // a = r2                                                                     <L 122>
                var_132 = wp::copy(var_7);
                // b = r3                                                                     <L 123>
                var_133 = wp::copy(var_13);
                // if nv == 3:                                                                <L 124>
                var_135 = (var_nv == var_134);
                if (var_135) {
                    // b = r0                                                                 <L 125>
                    var_136 = wp::copy(var_3);
                }
                var_137 = wp::where(var_135, var_136, var_133);
            }
            if (!var_131) {
                // elif k == 3:                                                               <L 126>
                var_139 = (var_119 == var_138);
                if (var_139) {
                    // a = r3                                                                 <L 127>
                    var_140 = wp::copy(var_13);
                    // b = r0                                                                 <L 128>
                    var_141 = wp::copy(var_3);
                }
                var_142 = wp::where(var_139, var_140, var_124);
                var_143 = wp::where(var_139, var_141, var_125);
            }
            var_144 = wp::where(var_131, var_132, var_142);
            var_145 = wp::where(var_131, var_137, var_143);
        }
        var_146 = wp::where(var_127, var_128, var_144);
        var_147 = wp::where(var_127, var_129, var_145);
        // ha = wp.dot(a, nd)                                                                 <L 129>
        var_148 = wp::dot(var_146, var_1);
        // hb = wp.dot(b, nd)                                                                 <L 130>
        var_149 = wp::dot(var_147, var_1);
        // if ha > f0 and hb > f0:                                                            <L 131>
        var_151 = (var_148 > var_14);
        var_150 = var_151;
        if (var_150) {
            var_152 = (var_149 > var_14);
            var_150 = var_150 && var_152;
        }
        if (var_150) {
            // total += _edge_term(wp.normalize(a), wp.normalize(b), nd)                      <L 132>
            var_153 = wp::normalize(var_146);
            var_154 = wp::normalize(var_147);
            var_155 = _edge_term_0(var_153, var_154, var_1);
            var_156 = wp::add(var_114, var_155);
        }
        if (!var_150) {
            // elif ha > f0 and hb <= f0:                                                     <L 133>
            var_158 = (var_148 > var_14);
            var_157 = var_158;
            if (var_157) {
                var_159 = (var_149 <= var_14);
                var_157 = var_157 && var_159;
            }
            if (var_157) {
                // x = a + (b - a) * (ha / (ha - hb))  # leaves the hemisphere                <L 134>
                var_160 = wp::sub(var_147, var_146);
                var_161 = wp::sub(var_148, var_149);
                var_162 = wp::div(var_148, var_161);
                var_163 = wp::mul(var_160, var_162);
                var_164 = wp::add(var_146, var_163);
                // total += _edge_term(wp.normalize(a), wp.normalize(x), nd)                  <L 135>
                var_165 = wp::normalize(var_146);
                var_166 = wp::normalize(var_164);
                var_167 = _edge_term_0(var_165, var_166, var_1);
                var_168 = wp::add(var_114, var_167);
                // exit_pt = x                                                                <L 136>
                var_169 = wp::copy(var_164);
                // have_exit = 1                                                              <L 137>
            }
            if (!var_157) {
                // elif ha <= f0 and hb > f0:                                                 <L 138>
                var_172 = (var_148 <= var_14);
                var_171 = var_172;
                if (var_171) {
                    var_173 = (var_149 > var_14);
                    var_171 = var_171 && var_173;
                }
                if (var_171) {
                    // x = a + (b - a) * (ha / (ha - hb))  # enters                           <L 139>
                    var_174 = wp::sub(var_147, var_146);
                    var_175 = wp::sub(var_148, var_149);
                    var_176 = wp::div(var_148, var_175);
                    var_177 = wp::mul(var_174, var_176);
                    var_178 = wp::add(var_146, var_177);
                    // total += _edge_term(wp.normalize(x), wp.normalize(b), nd)              <L 140>
                    var_179 = wp::normalize(var_178);
                    var_180 = wp::normalize(var_147);
                    var_181 = _edge_term_0(var_179, var_180, var_1);
                    var_182 = wp::add(var_114, var_181);
                    // if have_exit != 0:                                                     <L 141>
                    var_184 = (var_116 != var_183);
                    if (var_184) {
                        // total += _edge_term(wp.normalize(exit_pt), wp.normalize(x), nd)       <L 142>
                        var_185 = wp::normalize(var_115);
                        var_186 = wp::normalize(var_178);
                        var_187 = _edge_term_0(var_185, var_186, var_1);
                        var_188 = wp::add(var_182, var_187);
                        // have_exit = 0                                                      <L 143>
                    }
                    if (!var_184) {
                        // first_enter = x                                                    <L 145>
                        var_190 = wp::copy(var_178);
                        // pending_enter = 1                                                  <L 146>
                    }
                    var_192 = wp::where(var_184, var_188, var_182);
                    var_193 = wp::where(var_184, var_189, var_116);
                    var_194 = wp::where(var_184, var_117, var_190);
                    var_195 = wp::where(var_184, var_118, var_191);
                }
                var_196 = wp::where(var_171, var_192, var_114);
                var_197 = wp::where(var_171, var_193, var_116);
                var_198 = wp::where(var_171, var_194, var_117);
                var_199 = wp::where(var_171, var_195, var_118);
                var_200 = wp::where(var_171, var_178, var_108);
            }
            var_201 = wp::where(var_157, var_168, var_196);
            var_202 = wp::where(var_157, var_169, var_115);
            var_203 = wp::where(var_157, var_170, var_197);
            var_204 = wp::where(var_157, var_117, var_198);
            var_205 = wp::where(var_157, var_118, var_199);
            var_206 = wp::where(var_157, var_164, var_200);
        }
        var_207 = wp::where(var_150, var_156, var_201);
        var_208 = wp::where(var_150, var_115, var_202);
        var_209 = wp::where(var_150, var_116, var_203);
        var_210 = wp::where(var_150, var_117, var_204);
        var_211 = wp::where(var_150, var_118, var_205);
        var_212 = wp::where(var_150, var_108, var_206);
    }
    var_213 = wp::where(var_123, var_207, var_114);
    var_214 = wp::where(var_123, var_208, var_115);
    var_215 = wp::where(var_123, var_209, var_116);
    var_216 = wp::where(var_123, var_210, var_117);
    var_217 = wp::where(var_123, var_211, var_118);
    var_218 = wp::where(var_123, var_146, var_49);
    var_219 = wp::where(var_123, var_147, var_50);
    var_220 = wp::where(var_123, var_148, var_51);
    var_221 = wp::where(var_123, var_149, var_52);
    var_222 = wp::where(var_123, var_212, var_108);
    // if k >= nv:                                                                            <L 114>
    var_225 = (var_223 >= var_nv);
    if (var_225) {
        // continue                                                                           <L 115>
    }
    var_227 = wp::where(var_225, var_226, var_224);
    // a = r0                                                                                 <L 116>
    if (var_227) {
        var_228 = wp::copy(var_3);
        // b = r1                                                                             <L 117>
        var_229 = wp::copy(var_5);
        // if k == 1:                                                                         <L 118>
        var_231 = (var_223 == var_230);
        if (var_231) {
            // a = r1                                                                         <L 119>
            var_232 = wp::copy(var_5);
            // b = r2                                                                         <L 120>
            var_233 = wp::copy(var_7);
        }
        if (!var_231) {
            // elif k == 2:                                                                   <L 121>
            var_235 = (var_223 == var_234);
            if (var_235) {
                // a = r2                                                                     <L 122>
                var_236 = wp::copy(var_7);
                // b = r3                                                                     <L 123>
                var_237 = wp::copy(var_13);
                // if nv == 3:                                                                <L 124>
                var_239 = (var_nv == var_238);
                if (var_239) {
                    // b = r0                                                                 <L 125>
                    var_240 = wp::copy(var_3);
                }
                var_241 = wp::where(var_239, var_240, var_237);
            }
            if (!var_235) {
                // elif k == 3:                                                               <L 126>
                var_243 = (var_223 == var_242);
                if (var_243) {
                    // a = r3                                                                 <L 127>
                    var_244 = wp::copy(var_13);
                    // b = r0                                                                 <L 128>
                    var_245 = wp::copy(var_3);
                }
                var_246 = wp::where(var_243, var_244, var_228);
                var_247 = wp::where(var_243, var_245, var_229);
            }
            var_248 = wp::where(var_235, var_236, var_246);
            var_249 = wp::where(var_235, var_241, var_247);
        }
        var_250 = wp::where(var_231, var_232, var_248);
        var_251 = wp::where(var_231, var_233, var_249);
        // ha = wp.dot(a, nd)                                                                 <L 129>
        var_252 = wp::dot(var_250, var_1);
        // hb = wp.dot(b, nd)                                                                 <L 130>
        var_253 = wp::dot(var_251, var_1);
        // if ha > f0 and hb > f0:                                                            <L 131>
        var_255 = (var_252 > var_14);
        var_254 = var_255;
        if (var_254) {
            var_256 = (var_253 > var_14);
            var_254 = var_254 && var_256;
        }
        if (var_254) {
            // total += _edge_term(wp.normalize(a), wp.normalize(b), nd)                      <L 132>
            var_257 = wp::normalize(var_250);
            var_258 = wp::normalize(var_251);
            var_259 = _edge_term_0(var_257, var_258, var_1);
            var_260 = wp::add(var_213, var_259);
        }
        if (!var_254) {
            // elif ha > f0 and hb <= f0:                                                     <L 133>
            var_262 = (var_252 > var_14);
            var_261 = var_262;
            if (var_261) {
                var_263 = (var_253 <= var_14);
                var_261 = var_261 && var_263;
            }
            if (var_261) {
                // x = a + (b - a) * (ha / (ha - hb))  # leaves the hemisphere                <L 134>
                var_264 = wp::sub(var_251, var_250);
                var_265 = wp::sub(var_252, var_253);
                var_266 = wp::div(var_252, var_265);
                var_267 = wp::mul(var_264, var_266);
                var_268 = wp::add(var_250, var_267);
                // total += _edge_term(wp.normalize(a), wp.normalize(x), nd)                  <L 135>
                var_269 = wp::normalize(var_250);
                var_270 = wp::normalize(var_268);
                var_271 = _edge_term_0(var_269, var_270, var_1);
                var_272 = wp::add(var_213, var_271);
                // exit_pt = x                                                                <L 136>
                var_273 = wp::copy(var_268);
                // have_exit = 1                                                              <L 137>
            }
            if (!var_261) {
                // elif ha <= f0 and hb > f0:                                                 <L 138>
                var_276 = (var_252 <= var_14);
                var_275 = var_276;
                if (var_275) {
                    var_277 = (var_253 > var_14);
                    var_275 = var_275 && var_277;
                }
                if (var_275) {
                    // x = a + (b - a) * (ha / (ha - hb))  # enters                           <L 139>
                    var_278 = wp::sub(var_251, var_250);
                    var_279 = wp::sub(var_252, var_253);
                    var_280 = wp::div(var_252, var_279);
                    var_281 = wp::mul(var_278, var_280);
                    var_282 = wp::add(var_250, var_281);
                    // total += _edge_term(wp.normalize(x), wp.normalize(b), nd)              <L 140>
                    var_283 = wp::normalize(var_282);
                    var_284 = wp::normalize(var_251);
                    var_285 = _edge_term_0(var_283, var_284, var_1);
                    var_286 = wp::add(var_213, var_285);
                    // if have_exit != 0:                                                     <L 141>
                    var_288 = (var_215 != var_287);
                    if (var_288) {
                        // total += _edge_term(wp.normalize(exit_pt), wp.normalize(x), nd)       <L 142>
                        var_289 = wp::normalize(var_214);
                        var_290 = wp::normalize(var_282);
                        var_291 = _edge_term_0(var_289, var_290, var_1);
                        var_292 = wp::add(var_286, var_291);
                        // have_exit = 0                                                      <L 143>
                    }
                    if (!var_288) {
                        // first_enter = x                                                    <L 145>
                        var_294 = wp::copy(var_282);
                        // pending_enter = 1                                                  <L 146>
                    }
                    var_296 = wp::where(var_288, var_292, var_286);
                    var_297 = wp::where(var_288, var_293, var_215);
                    var_298 = wp::where(var_288, var_216, var_294);
                    var_299 = wp::where(var_288, var_217, var_295);
                }
                var_300 = wp::where(var_275, var_296, var_213);
                var_301 = wp::where(var_275, var_297, var_215);
                var_302 = wp::where(var_275, var_298, var_216);
                var_303 = wp::where(var_275, var_299, var_217);
                var_304 = wp::where(var_275, var_282, var_222);
            }
            var_305 = wp::where(var_261, var_272, var_300);
            var_306 = wp::where(var_261, var_273, var_214);
            var_307 = wp::where(var_261, var_274, var_301);
            var_308 = wp::where(var_261, var_216, var_302);
            var_309 = wp::where(var_261, var_217, var_303);
            var_310 = wp::where(var_261, var_268, var_304);
        }
        var_311 = wp::where(var_254, var_260, var_305);
        var_312 = wp::where(var_254, var_214, var_306);
        var_313 = wp::where(var_254, var_215, var_307);
        var_314 = wp::where(var_254, var_216, var_308);
        var_315 = wp::where(var_254, var_217, var_309);
        var_316 = wp::where(var_254, var_222, var_310);
    }
    var_317 = wp::where(var_227, var_311, var_213);
    var_318 = wp::where(var_227, var_312, var_214);
    var_319 = wp::where(var_227, var_313, var_215);
    var_320 = wp::where(var_227, var_314, var_216);
    var_321 = wp::where(var_227, var_315, var_217);
    var_322 = wp::where(var_227, var_250, var_218);
    var_323 = wp::where(var_227, var_251, var_219);
    var_324 = wp::where(var_227, var_252, var_220);
    var_325 = wp::where(var_227, var_253, var_221);
    var_326 = wp::where(var_227, var_316, var_222);
    // if k >= nv:                                                                            <L 114>
    var_329 = (var_327 >= var_nv);
    if (var_329) {
        // continue                                                                           <L 115>
    }
    var_331 = wp::where(var_329, var_330, var_328);
    // a = r0                                                                                 <L 116>
    if (var_331) {
        var_332 = wp::copy(var_3);
        // b = r1                                                                             <L 117>
        var_333 = wp::copy(var_5);
        // if k == 1:                                                                         <L 118>
        var_335 = (var_327 == var_334);
        if (var_335) {
            // a = r1                                                                         <L 119>
            var_336 = wp::copy(var_5);
            // b = r2                                                                         <L 120>
            var_337 = wp::copy(var_7);
        }
        if (!var_335) {
            // elif k == 2:                                                                   <L 121>
            var_339 = (var_327 == var_338);
            if (var_339) {
                // a = r2                                                                     <L 122>
                var_340 = wp::copy(var_7);
                // b = r3                                                                     <L 123>
                var_341 = wp::copy(var_13);
                // if nv == 3:                                                                <L 124>
                var_343 = (var_nv == var_342);
                if (var_343) {
                    // b = r0                                                                 <L 125>
                    var_344 = wp::copy(var_3);
                }
                var_345 = wp::where(var_343, var_344, var_341);
            }
            if (!var_339) {
                // elif k == 3:                                                               <L 126>
                var_347 = (var_327 == var_346);
                if (var_347) {
                    // a = r3                                                                 <L 127>
                    var_348 = wp::copy(var_13);
                    // b = r0                                                                 <L 128>
                    var_349 = wp::copy(var_3);
                }
                var_350 = wp::where(var_347, var_348, var_332);
                var_351 = wp::where(var_347, var_349, var_333);
            }
            var_352 = wp::where(var_339, var_340, var_350);
            var_353 = wp::where(var_339, var_345, var_351);
        }
        var_354 = wp::where(var_335, var_336, var_352);
        var_355 = wp::where(var_335, var_337, var_353);
        // ha = wp.dot(a, nd)                                                                 <L 129>
        var_356 = wp::dot(var_354, var_1);
        // hb = wp.dot(b, nd)                                                                 <L 130>
        var_357 = wp::dot(var_355, var_1);
        // if ha > f0 and hb > f0:                                                            <L 131>
        var_359 = (var_356 > var_14);
        var_358 = var_359;
        if (var_358) {
            var_360 = (var_357 > var_14);
            var_358 = var_358 && var_360;
        }
        if (var_358) {
            // total += _edge_term(wp.normalize(a), wp.normalize(b), nd)                      <L 132>
            var_361 = wp::normalize(var_354);
            var_362 = wp::normalize(var_355);
            var_363 = _edge_term_0(var_361, var_362, var_1);
            var_364 = wp::add(var_317, var_363);
        }
        if (!var_358) {
            // elif ha > f0 and hb <= f0:                                                     <L 133>
            var_366 = (var_356 > var_14);
            var_365 = var_366;
            if (var_365) {
                var_367 = (var_357 <= var_14);
                var_365 = var_365 && var_367;
            }
            if (var_365) {
                // x = a + (b - a) * (ha / (ha - hb))  # leaves the hemisphere                <L 134>
                var_368 = wp::sub(var_355, var_354);
                var_369 = wp::sub(var_356, var_357);
                var_370 = wp::div(var_356, var_369);
                var_371 = wp::mul(var_368, var_370);
                var_372 = wp::add(var_354, var_371);
                // total += _edge_term(wp.normalize(a), wp.normalize(x), nd)                  <L 135>
                var_373 = wp::normalize(var_354);
                var_374 = wp::normalize(var_372);
                var_375 = _edge_term_0(var_373, var_374, var_1);
                var_376 = wp::add(var_317, var_375);
                // exit_pt = x                                                                <L 136>
                var_377 = wp::copy(var_372);
                // have_exit = 1                                                              <L 137>
            }
            if (!var_365) {
                // elif ha <= f0 and hb > f0:                                                 <L 138>
                var_380 = (var_356 <= var_14);
                var_379 = var_380;
                if (var_379) {
                    var_381 = (var_357 > var_14);
                    var_379 = var_379 && var_381;
                }
                if (var_379) {
                    // x = a + (b - a) * (ha / (ha - hb))  # enters                           <L 139>
                    var_382 = wp::sub(var_355, var_354);
                    var_383 = wp::sub(var_356, var_357);
                    var_384 = wp::div(var_356, var_383);
                    var_385 = wp::mul(var_382, var_384);
                    var_386 = wp::add(var_354, var_385);
                    // total += _edge_term(wp.normalize(x), wp.normalize(b), nd)              <L 140>
                    var_387 = wp::normalize(var_386);
                    var_388 = wp::normalize(var_355);
                    var_389 = _edge_term_0(var_387, var_388, var_1);
                    var_390 = wp::add(var_317, var_389);
                    // if have_exit != 0:                                                     <L 141>
                    var_392 = (var_319 != var_391);
                    if (var_392) {
                        // total += _edge_term(wp.normalize(exit_pt), wp.normalize(x), nd)       <L 142>
                        var_393 = wp::normalize(var_318);
                        var_394 = wp::normalize(var_386);
                        var_395 = _edge_term_0(var_393, var_394, var_1);
                        var_396 = wp::add(var_390, var_395);
                        // have_exit = 0                                                      <L 143>
                    }
                    if (!var_392) {
                        // first_enter = x                                                    <L 145>
                        var_398 = wp::copy(var_386);
                        // pending_enter = 1                                                  <L 146>
                    }
                    var_400 = wp::where(var_392, var_396, var_390);
                    var_401 = wp::where(var_392, var_397, var_319);
                    var_402 = wp::where(var_392, var_320, var_398);
                    var_403 = wp::where(var_392, var_321, var_399);
                }
                var_404 = wp::where(var_379, var_400, var_317);
                var_405 = wp::where(var_379, var_401, var_319);
                var_406 = wp::where(var_379, var_402, var_320);
                var_407 = wp::where(var_379, var_403, var_321);
                var_408 = wp::where(var_379, var_386, var_326);
            }
            var_409 = wp::where(var_365, var_376, var_404);
            var_410 = wp::where(var_365, var_377, var_318);
            var_411 = wp::where(var_365, var_378, var_405);
            var_412 = wp::where(var_365, var_320, var_406);
            var_413 = wp::where(var_365, var_321, var_407);
            var_414 = wp::where(var_365, var_372, var_408);
        }
        var_415 = wp::where(var_358, var_364, var_409);
        var_416 = wp::where(var_358, var_318, var_410);
        var_417 = wp::where(var_358, var_319, var_411);
        var_418 = wp::where(var_358, var_320, var_412);
        var_419 = wp::where(var_358, var_321, var_413);
        var_420 = wp::where(var_358, var_326, var_414);
    }
    var_421 = wp::where(var_331, var_415, var_317);
    var_422 = wp::where(var_331, var_416, var_318);
    var_423 = wp::where(var_331, var_417, var_319);
    var_424 = wp::where(var_331, var_418, var_320);
    var_425 = wp::where(var_331, var_419, var_321);
    var_426 = wp::where(var_331, var_354, var_322);
    var_427 = wp::where(var_331, var_355, var_323);
    var_428 = wp::where(var_331, var_356, var_324);
    var_429 = wp::where(var_331, var_357, var_325);
    var_430 = wp::where(var_331, var_420, var_326);
    // if have_exit != 0 and pending_enter != 0:                                              <L 147>
    var_433 = (var_423 != var_432);
    var_431 = var_433;
    if (var_431) {
        var_435 = (var_425 != var_434);
        var_431 = var_431 && var_435;
    }
    if (var_431) {
        // total += _edge_term(wp.normalize(exit_pt), wp.normalize(first_enter), nd)          <L 148>
        var_436 = wp::normalize(var_422);
        var_437 = wp::normalize(var_424);
        var_438 = _edge_term_0(var_436, var_437, var_1);
        var_439 = wp::add(var_421, var_438);
    }
    var_440 = wp::where(var_431, var_439, var_421);
    // return float(wp.float64(0.5) * wp.abs(total))                                          <L 149>
    var_441 = 0.5;
    var_442 = wp::abs(var_440);
    var_443 = wp::mul(var_441, var_442);
    var_444 = wp::float(var_443);
    return var_444;
}


// /work/main/simulator/kernels/lights/dome.py:94
static wp::float32 portal_weight_0(
    PortalRec_445c1fd2 var_pt,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    bool var_single)
{
    //---------
    // primal vars
    bool var_0;
    bool var_1;
    const wp::float32 var_2 = 0.0;
    const wp::float32 var_3 = 1.0;
    const wp::int32 var_4 = 1;
    const wp::int32 var_5 = 0;
    bool var_6;
    wp::vec_t<3, wp::float32>* var_7;
    wp::float32* var_8;
    wp::vec_t<3, wp::float32>* var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::float32 var_11;
    wp::vec_t<3, wp::float32> var_12;
    wp::vec_t<3, wp::float32> var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::vec_t<3, wp::float32>* var_15;
    wp::float32* var_16;
    wp::vec_t<3, wp::float32>* var_17;
    wp::vec_t<3, wp::float32> var_18;
    wp::float32 var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32>* var_23;
    wp::float32* var_24;
    wp::vec_t<3, wp::float32>* var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::float32 var_27;
    wp::vec_t<3, wp::float32> var_28;
    wp::vec_t<3, wp::float32> var_29;
    const wp::int32 var_30 = 4;
    wp::float32 var_31;
    wp::vec_t<3, wp::float32> var_32;
    wp::vec_t<3, wp::float32>* var_33;
    wp::vec_t<3, wp::float32>* var_34;
    wp::vec_t<3, wp::float32>* var_35;
    wp::float32* var_36;
    wp::float32* var_37;
    SphRect_7f5b29ec var_38;
    wp::vec_t<3, wp::float32> var_39;
    wp::vec_t<3, wp::float32> var_40;
    wp::vec_t<3, wp::float32> var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    wp::float32* var_44;
    wp::float32 var_45;
    wp::float32 var_46;
    //---------
    // forward
    // def portal_weight(pt: PortalRec, p: wp.vec3, n: wp.vec3, single: bool) -> float:       <L 95>
    // if not portal_guides(pt, p, n):                                                        <L 100>
    var_0 = portal_guides_0(var_pt, var_p, var_n);
    var_1 = wp::unot(var_0);
    if (var_1) {
        // return 0.0                                                                         <L 101>
        return var_2;
    }
    // if single:                                                                             <L 102>
    if (var_single) {
        // return 1.0                                                                         <L 103>
        return var_3;
    }
    // if PORTAL_PICK_PROJECTED != 0:                                                         <L 104>
    var_6 = (var_4 != var_5);
    if (var_6) {
        // c1 = pt.corner + pt.width * pt.ex                                                  <L 105>
        var_7 = &((var_pt).corner);
        var_8 = &((var_pt).width);
        var_9 = &((var_pt).ex);
        var_11 = wp::load(var_8);
        var_12 = wp::load(var_9);
        var_10 = wp::mul(var_11, var_12);
        var_14 = wp::load(var_7);
        var_13 = wp::add(var_14, var_10);
        // c3 = pt.corner + pt.height * pt.ey                                                 <L 106>
        var_15 = &((var_pt).corner);
        var_16 = &((var_pt).height);
        var_17 = &((var_pt).ey);
        var_19 = wp::load(var_16);
        var_20 = wp::load(var_17);
        var_18 = wp::mul(var_19, var_20);
        var_22 = wp::load(var_15);
        var_21 = wp::add(var_22, var_18);
        // return polygon_irradiance4(pt.corner, c1, c1 + pt.height * pt.ey, c3, 4, p, n)       <L 107>
        var_23 = &((var_pt).corner);
        var_24 = &((var_pt).height);
        var_25 = &((var_pt).ey);
        var_27 = wp::load(var_24);
        var_28 = wp::load(var_25);
        var_26 = wp::mul(var_27, var_28);
        var_29 = wp::add(var_13, var_26);
        var_32 = wp::load(var_23);
        var_31 = polygon_irradiance4_0(var_32, var_13, var_29, var_21, var_30, var_p, var_n);
        return var_31;
    }
    // return sphrect_setup(p, pt.corner, pt.ex, pt.ey, pt.width, pt.height).solid_angle       <L 108>
    var_33 = &((var_pt).corner);
    var_34 = &((var_pt).ex);
    var_35 = &((var_pt).ey);
    var_36 = &((var_pt).width);
    var_37 = &((var_pt).height);
    var_39 = wp::load(var_33);
    var_40 = wp::load(var_34);
    var_41 = wp::load(var_35);
    var_42 = wp::load(var_36);
    var_43 = wp::load(var_37);
    var_38 = sphrect_setup_0(var_p, var_39, var_40, var_41, var_42, var_43);
    var_44 = &(var_38.solid_angle);
    var_46 = wp::load(var_44);
    var_45 = wp::copy(var_46);
    return var_45;
}


// /work/main/simulator/kernels/lights/dome.py:111
static wp::float32 portals_total_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    wp::float32 var_1;
    wp::int32* var_2;
    const wp::int32 var_3 = 1;
    bool var_4;
    wp::int32 var_5;
    wp::int32* var_6;
    wp::range_t var_7;
    wp::int32 var_8;
    wp::int32 var_9;
    wp::array_t<PortalRec_445c1fd2>* var_10;
    PortalRec_445c1fd2* var_11;
    wp::array_t<PortalRec_445c1fd2> var_12;
    wp::float32 var_13;
    PortalRec_445c1fd2 var_14;
    wp::float32 var_15;
    //---------
    // forward
    // def portals_total(l: LightRec, p: wp.vec3, n: wp.vec3) -> float:                       <L 112>
    // total = float(0.0)                                                                     <L 114>
    var_1 = wp::float(var_0);
    // single = l.n_portals == 1                                                              <L 115>
    var_2 = &((var_l).n_portals);
    var_5 = wp::load(var_2);
    var_4 = (var_5 == var_3);
    // for j in range(l.n_portals):                                                           <L 116>
    var_6 = &((var_l).n_portals);
    var_8 = wp::load(var_6);
    var_7 = wp::range(var_8);
    start_for_0:;
        if (iter_cmp(var_7) == 0) goto end_for_0;
        var_9 = wp::iter_next(var_7);
        // total += portal_weight(l.portals[j], p, n, single)                                 <L 117>
        var_10 = &((var_l).portals);
        var_12 = wp::load(var_10);
        var_11 = wp::address(var_12, var_9);
        var_14 = wp::load(var_11);
        var_13 = portal_weight_0(var_14, var_p, var_n, var_4);
        var_15 = wp::add(var_1, var_13);
        wp::assign(var_1, var_15);
        goto start_for_0;
    end_for_0:;
    // return total                                                                           <L 118>
    return var_1;
}


// /work/main/simulator/kernels/lights/dome.py:121
static wp::float32 portal_density_0(
    PortalRec_445c1fd2 var_pt,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_wi)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::float32 var_1;
    wp::vec_t<3, wp::float32> var_2;
    const wp::float32 var_3 = 0.0;
    bool var_4;
    const wp::float32 var_5 = 0.0;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32>* var_9;
    wp::float32 var_10;
    wp::vec_t<3, wp::float32> var_11;
    wp::float32 var_12;
    const wp::float32 var_13 = 0.0;
    bool var_14;
    const wp::float32 var_15 = 0.0;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::vec_t<3, wp::float32>* var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32>* var_21;
    wp::float32 var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32>* var_24;
    wp::float32 var_25;
    wp::vec_t<3, wp::float32> var_26;
    bool var_27;
    const wp::float32 var_28 = 0.0;
    bool var_29;
    wp::float32* var_30;
    bool var_31;
    wp::float32 var_32;
    const wp::float32 var_33 = 0.0;
    bool var_34;
    wp::float32* var_35;
    bool var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 0.0;
    wp::vec_t<3, wp::float32>* var_39;
    wp::vec_t<3, wp::float32>* var_40;
    wp::vec_t<3, wp::float32>* var_41;
    wp::float32* var_42;
    wp::float32* var_43;
    SphRect_7f5b29ec var_44;
    wp::vec_t<3, wp::float32> var_45;
    wp::vec_t<3, wp::float32> var_46;
    wp::vec_t<3, wp::float32> var_47;
    wp::float32 var_48;
    wp::float32 var_49;
    wp::float32* var_50;
    const wp::float32 var_51 = 0.0001;
    bool var_52;
    wp::float32 var_53;
    const wp::float32 var_54 = 1.0;
    wp::float32* var_55;
    wp::float32 var_56;
    wp::float32 var_57;
    wp::float32 var_58;
    wp::float32* var_59;
    wp::float32* var_60;
    wp::float32 var_61;
    wp::float32 var_62;
    wp::float32 var_63;
    wp::float32 var_64;
    wp::float32 var_65;
    //---------
    // forward
    // def portal_density(pt: PortalRec, p: wp.vec3, wi: wp.vec3) -> float:                   <L 122>
    // denom = wp.dot(wi, pt.ez)                                                              <L 127>
    var_0 = &((var_pt).ez);
    var_2 = wp::load(var_0);
    var_1 = wp::dot(var_wi, var_2);
    // if denom <= 0.0:                                                                       <L 128>
    var_4 = (var_1 <= var_3);
    if (var_4) {
        // return 0.0                                                                         <L 129>
        return var_5;
    }
    // t = wp.dot(pt.corner - p, pt.ez) / denom                                               <L 130>
    var_6 = &((var_pt).corner);
    var_8 = wp::load(var_6);
    var_7 = wp::sub(var_8, var_p);
    var_9 = &((var_pt).ez);
    var_11 = wp::load(var_9);
    var_10 = wp::dot(var_7, var_11);
    var_12 = wp::div(var_10, var_1);
    // if t <= 0.0:                                                                           <L 131>
    var_14 = (var_12 <= var_13);
    if (var_14) {
        // return 0.0                                                                         <L 132>
        return var_15;
    }
    // q = p + t * wi - pt.corner                                                             <L 133>
    var_16 = wp::mul(var_12, var_wi);
    var_17 = wp::add(var_p, var_16);
    var_18 = &((var_pt).corner);
    var_20 = wp::load(var_18);
    var_19 = wp::sub(var_17, var_20);
    // x = wp.dot(q, pt.ex)                                                                   <L 134>
    var_21 = &((var_pt).ex);
    var_23 = wp::load(var_21);
    var_22 = wp::dot(var_19, var_23);
    // y = wp.dot(q, pt.ey)                                                                   <L 135>
    var_24 = &((var_pt).ey);
    var_26 = wp::load(var_24);
    var_25 = wp::dot(var_19, var_26);
    // if x < 0.0 or x > pt.width or y < 0.0 or y > pt.height:                                <L 136>
    var_29 = (var_22 < var_28);
    var_27 = var_29;
    if (!var_27) {
        var_30 = &((var_pt).width);
        var_32 = wp::load(var_30);
        var_31 = (var_22 > var_32);
        var_27 = var_27 || var_31;
    }
    if (!var_27) {
        var_34 = (var_25 < var_33);
        var_27 = var_27 || var_34;
    }
    if (!var_27) {
        var_35 = &((var_pt).height);
        var_37 = wp::load(var_35);
        var_36 = (var_25 > var_37);
        var_27 = var_27 || var_36;
    }
    if (var_27) {
        // return 0.0                                                                         <L 137>
        return var_38;
    }
    // sr = sphrect_setup(p, pt.corner, pt.ex, pt.ey, pt.width, pt.height)                    <L 138>
    var_39 = &((var_pt).corner);
    var_40 = &((var_pt).ex);
    var_41 = &((var_pt).ey);
    var_42 = &((var_pt).width);
    var_43 = &((var_pt).height);
    var_45 = wp::load(var_39);
    var_46 = wp::load(var_40);
    var_47 = wp::load(var_41);
    var_48 = wp::load(var_42);
    var_49 = wp::load(var_43);
    var_44 = sphrect_setup_0(var_p, var_45, var_46, var_47, var_48, var_49);
    // if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:                                           <L 139>
    var_50 = &((var_44).solid_angle);
    var_53 = wp::load(var_50);
    var_52 = (var_53 > var_51);
    if (var_52) {
        // return 1.0 / sr.solid_angle                                                        <L 140>
        var_55 = &((var_44).solid_angle);
        var_57 = wp::load(var_55);
        var_56 = wp::div(var_54, var_57);
        return var_56;
    }
    // return t * t / (pt.width * pt.height * denom)                                          <L 141>
    var_58 = wp::mul(var_12, var_12);
    var_59 = &((var_pt).width);
    var_60 = &((var_pt).height);
    var_62 = wp::load(var_59);
    var_63 = wp::load(var_60);
    var_61 = wp::mul(var_62, var_63);
    var_64 = wp::mul(var_61, var_1);
    var_65 = wp::div(var_58, var_64);
    return var_65;
}


// /work/main/simulator/kernels/lights/dome.py:144
static wp::float32 pdf_portals_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_total,
    wp::int32 var_skip)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    wp::float32 var_1;
    wp::int32* var_2;
    const wp::int32 var_3 = 1;
    bool var_4;
    wp::int32 var_5;
    wp::int32* var_6;
    wp::range_t var_7;
    wp::int32 var_8;
    wp::int32 var_9;
    bool var_10;
    wp::array_t<PortalRec_445c1fd2>* var_11;
    PortalRec_445c1fd2* var_12;
    wp::array_t<PortalRec_445c1fd2> var_13;
    PortalRec_445c1fd2 var_14;
    PortalRec_445c1fd2 var_15;
    wp::float32 var_16;
    const wp::float32 var_17 = 0.0;
    bool var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::float32 var_24;
    //---------
    // forward
    // def pdf_portals(l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, total: float, skip: int) -> float:       <L 145>
    // acc = float(0.0)                                                                       <L 148>
    var_1 = wp::float(var_0);
    // single = l.n_portals == 1                                                              <L 149>
    var_2 = &((var_l).n_portals);
    var_5 = wp::load(var_2);
    var_4 = (var_5 == var_3);
    // for j in range(l.n_portals):                                                           <L 150>
    var_6 = &((var_l).n_portals);
    var_8 = wp::load(var_6);
    var_7 = wp::range(var_8);
    start_for_0:;
        if (iter_cmp(var_7) == 0) goto end_for_0;
        var_9 = wp::iter_next(var_7);
        // if j != skip:                                                                      <L 151>
        var_10 = (var_9 != var_skip);
        if (var_10) {
            // pt = l.portals[j]                                                              <L 152>
            var_11 = &((var_l).portals);
            var_13 = wp::load(var_11);
            var_12 = wp::address(var_13, var_9);
            var_15 = wp::load(var_12);
            var_14 = wp::copy(var_15);
            // wj = portal_weight(pt, p, n, single)                                           <L 153>
            var_16 = portal_weight_0(var_14, var_p, var_n, var_4);
            // if wj > 0.0:                                                                   <L 154>
            var_18 = (var_16 > var_17);
            if (var_18) {
                // acc += (wj / total) * portal_density(pt, p, wi)                            <L 155>
                var_19 = wp::div(var_16, var_total);
                var_20 = portal_density_0(var_14, var_p, var_wi);
                var_21 = wp::mul(var_19, var_20);
                var_22 = wp::add(var_1, var_21);
            }
            var_23 = wp::where(var_18, var_22, var_1);
        }
        var_24 = wp::where(var_10, var_23, var_1);
        wp::assign(var_1, var_24);
        goto start_for_0;
    end_for_0:;
    // return acc                                                                             <L 156>
    return var_1;
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


// /work/main/simulator/kernels/distributions.py:129
static wp::int32 latlong_texel_0(
    wp::vec_t<2, wp::float32> var_uv,
    wp::int32 var_w,
    wp::int32 var_h)
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
    wp::int32 var_18;
    wp::int32 var_19;
    //---------
    // forward
    // def latlong_texel(uv: wp.vec2, w: int, h: int) -> int:                                 <L 130>
    // i = wp.clamp(int(uv[0] * float(w)), 0, w - 1)                                          <L 132>
    var_1 = wp::extract(var_uv, var_0);
    var_2 = wp::float(var_w);
    var_3 = wp::mul(var_1, var_2);
    var_4 = wp::int(var_3);
    var_7 = wp::sub(var_w, var_6);
    var_8 = wp::clamp(var_4, var_5, var_7);
    // j = wp.clamp(int(uv[1] * float(h)), 0, h - 1)                                          <L 133>
    var_10 = wp::extract(var_uv, var_9);
    var_11 = wp::float(var_h);
    var_12 = wp::mul(var_10, var_11);
    var_13 = wp::int(var_12);
    var_16 = wp::sub(var_h, var_15);
    var_17 = wp::clamp(var_13, var_14, var_16);
    // return j * w + i                                                                       <L 134>
    var_18 = wp::mul(var_17, var_w);
    var_19 = wp::add(var_18, var_8);
    return var_19;
}


// /work/main/simulator/kernels/lights/dome.py:67
static wp::vec_t<2, wp::float32> escaped_1(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_d)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<3, wp::float32>* var_4;
    wp::vec_t<3, wp::float32>* var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<2, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<2, wp::float32>* var_11;
    wp::array_t<wp::float32>* var_12;
    wp::int32* var_13;
    wp::int32* var_14;
    wp::int32 var_15;
    wp::int32 var_16;
    wp::int32 var_17;
    wp::float32* var_18;
    wp::array_t<wp::float32> var_19;
    wp::vec_t<2, wp::float32> var_20;
    wp::vec_t<2, wp::float32> var_21;
    wp::float32 var_22;
    wp::vec_t<2, wp::float32>* var_23;
    wp::vec_t<2, wp::float32> var_24;
    wp::vec_t<2, wp::float32> var_25;
    //---------
    // forward
    // def escaped(l: LightRec, d: wp.vec3) -> wp.vec2:                                       <L 68>
    // if l.has_map != 0:                                                                     <L 69>
    var_0 = &((var_l).has_map);
    var_3 = wp::load(var_0);
    var_2 = (var_3 != var_1);
    if (var_2) {
        // uv = direction_to_latlong_uv(d, l.ex, l.ey, l.ez)                                  <L 70>
        var_4 = &((var_l).ex);
        var_5 = &((var_l).ey);
        var_6 = &((var_l).ez);
        var_8 = wp::load(var_4);
        var_9 = wp::load(var_5);
        var_10 = wp::load(var_6);
        var_7 = direction_to_latlong_uv_0(var_d, var_8, var_9, var_10);
        // return l.emission * l.map[latlong_texel(uv, l.map_w, l.map_h)]                     <L 71>
        var_11 = &((var_l).emission);
        var_12 = &((var_l).map);
        var_13 = &((var_l).map_w);
        var_14 = &((var_l).map_h);
        var_16 = wp::load(var_13);
        var_17 = wp::load(var_14);
        var_15 = latlong_texel_0(var_7, var_16, var_17);
        var_19 = wp::load(var_12);
        var_18 = wp::address(var_19, var_15);
        var_21 = wp::load(var_11);
        var_22 = wp::load(var_18);
        var_20 = wp::mul(var_21, var_22);
        return var_20;
    }
    // return l.emission                                                                      <L 72>
    var_23 = &((var_l).emission);
    var_25 = wp::load(var_23);
    var_24 = wp::copy(var_25);
    return var_24;
}


// /work/main/simulator/kernels/lights/dome.py:159
static LightSample_1981fb4b sample_portals_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    wp::float32 var_total)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::int32* var_1;
    const wp::int32 var_2 = 1;
    bool var_3;
    wp::int32 var_4;
    const wp::int32 var_5 = 2;
    wp::float32 var_6;
    wp::float32 var_7;
    const wp::int32 var_8 = -1;
    wp::int32 var_9;
    const wp::float32 var_10 = 0.0;
    wp::float32 var_11;
    const wp::float32 var_12 = 0.0;
    wp::float32 var_13;
    wp::int32* var_14;
    wp::range_t var_15;
    wp::int32 var_16;
    wp::int32 var_17;
    wp::array_t<PortalRec_445c1fd2>* var_18;
    PortalRec_445c1fd2* var_19;
    wp::array_t<PortalRec_445c1fd2> var_20;
    wp::float32 var_21;
    PortalRec_445c1fd2 var_22;
    const wp::float32 var_23 = 0.0;
    bool var_24;
    wp::int32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    bool var_28;
    wp::int32 var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::int32 var_32;
    wp::float32 var_33;
    wp::float32 var_34;
    const wp::int32 var_35 = 0;
    bool var_36;
    wp::array_t<PortalRec_445c1fd2>* var_37;
    PortalRec_445c1fd2* var_38;
    wp::array_t<PortalRec_445c1fd2> var_39;
    PortalRec_445c1fd2 var_40;
    PortalRec_445c1fd2 var_41;
    wp::vec_t<3, wp::float32>* var_42;
    wp::vec_t<3, wp::float32>* var_43;
    wp::vec_t<3, wp::float32>* var_44;
    wp::float32* var_45;
    wp::float32* var_46;
    SphRect_7f5b29ec var_47;
    wp::vec_t<3, wp::float32> var_48;
    wp::vec_t<3, wp::float32> var_49;
    wp::vec_t<3, wp::float32> var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    const wp::float32 var_53 = 0.0;
    const wp::float32 var_54 = 0.0;
    const wp::float32 var_55 = 1.0;
    wp::vec_t<3, wp::float32> var_56;
    const wp::float32 var_57 = 0.0;
    wp::float32 var_58;
    wp::float32* var_59;
    const wp::float32 var_60 = 0.0001;
    bool var_61;
    wp::float32 var_62;
    const wp::int32 var_63 = 0;
    wp::float32 var_64;
    const wp::int32 var_65 = 1;
    wp::float32 var_66;
    wp::vec_t<2, wp::float32> var_67;
    wp::vec_t<3, wp::float32> var_68;
    wp::vec_t<3, wp::float32> var_69;
    wp::vec_t<3, wp::float32> var_70;
    const wp::float32 var_71 = 1.0;
    wp::float32* var_72;
    wp::float32 var_73;
    wp::float32 var_74;
    wp::vec_t<3, wp::float32>* var_75;
    const wp::int32 var_76 = 0;
    wp::float32 var_77;
    wp::float32* var_78;
    wp::float32 var_79;
    wp::float32 var_80;
    wp::vec_t<3, wp::float32>* var_81;
    wp::vec_t<3, wp::float32> var_82;
    wp::vec_t<3, wp::float32> var_83;
    wp::vec_t<3, wp::float32> var_84;
    wp::vec_t<3, wp::float32> var_85;
    const wp::int32 var_86 = 1;
    wp::float32 var_87;
    wp::float32* var_88;
    wp::float32 var_89;
    wp::float32 var_90;
    wp::vec_t<3, wp::float32>* var_91;
    wp::vec_t<3, wp::float32> var_92;
    wp::vec_t<3, wp::float32> var_93;
    wp::vec_t<3, wp::float32> var_94;
    wp::vec_t<3, wp::float32> var_95;
    wp::float32 var_96;
    const wp::float32 var_97 = 0.0;
    bool var_98;
    wp::vec_t<3, wp::float32> var_99;
    wp::vec_t<3, wp::float32>* var_100;
    wp::float32 var_101;
    wp::vec_t<3, wp::float32> var_102;
    const wp::float32 var_103 = 0.0;
    bool var_104;
    wp::float32 var_105;
    wp::float32* var_106;
    wp::float32* var_107;
    wp::float32 var_108;
    wp::float32 var_109;
    wp::float32 var_110;
    wp::float32 var_111;
    wp::float32 var_112;
    wp::vec_t<3, wp::float32> var_113;
    wp::float32 var_114;
    wp::float32 var_115;
    wp::float32 var_116;
    bool var_117;
    wp::float32 var_118;
    wp::float32 var_119;
    wp::float32 var_120;
    const wp::float32 var_121 = 1e+30;
    wp::float32 var_122;
    const wp::float32 var_123 = 0.0;
    bool var_124;
    wp::vec_t<2, wp::float32> var_125;
    wp::float32 var_126;
    wp::vec_t<2, wp::float32> var_127;
    //---------
    // forward
    // def sample_portals(l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3, total: float) -> LightSample:       <L 160>
    // s = empty_sample()                                                                     <L 163>
    var_0 = empty_sample_0();
    // single = l.n_portals == 1                                                              <L 164>
    var_1 = &((var_l).n_portals);
    var_4 = wp::load(var_1);
    var_3 = (var_4 == var_2);
    // target = u[2] * total                                                                  <L 165>
    var_6 = wp::extract(var_u, var_5);
    var_7 = wp::mul(var_6, var_total);
    // k = int(-1)                                                                            <L 166>
    var_9 = wp::int(var_8);
    // wk = float(0.0)                                                                        <L 167>
    var_11 = wp::float(var_10);
    // acc = float(0.0)                                                                       <L 168>
    var_13 = wp::float(var_12);
    // for j in range(l.n_portals):                                                           <L 169>
    var_14 = &((var_l).n_portals);
    var_16 = wp::load(var_14);
    var_15 = wp::range(var_16);
    start_for_0:;
        if (iter_cmp(var_15) == 0) goto end_for_0;
        var_17 = wp::iter_next(var_15);
        // wj = portal_weight(l.portals[j], p, n, single)                                     <L 170>
        var_18 = &((var_l).portals);
        var_20 = wp::load(var_18);
        var_19 = wp::address(var_20, var_17);
        var_22 = wp::load(var_19);
        var_21 = portal_weight_0(var_22, var_p, var_n, var_3);
        // if wj > 0.0:                                                                       <L 171>
        var_24 = (var_21 > var_23);
        if (var_24) {
            // k = j                                                                          <L 172>
            var_25 = wp::copy(var_17);
            // wk = wj                                                                        <L 173>
            var_26 = wp::copy(var_21);
            // acc += wj                                                                      <L 174>
            var_27 = wp::add(var_13, var_21);
            // if target < acc:                                                               <L 175>
            var_28 = (var_7 < var_27);
            if (var_28) {
                // break                                                                      <L 176>
                wp::assign(var_9, var_25);
                wp::assign(var_11, var_26);
                wp::assign(var_13, var_27);
                goto end_for_0;
            }
            var_29 = wp::where(var_28, var_9, var_25);
            var_30 = wp::where(var_28, var_11, var_26);
            var_31 = wp::where(var_28, var_13, var_27);
        }
        var_32 = wp::where(var_24, var_29, var_9);
        var_33 = wp::where(var_24, var_30, var_11);
        var_34 = wp::where(var_24, var_31, var_13);
        wp::assign(var_9, var_32);
        wp::assign(var_11, var_33);
        wp::assign(var_13, var_34);
        goto start_for_0;
    end_for_0:;
    // if k < 0:                                                                              <L 177>
    var_36 = (var_9 < var_35);
    if (var_36) {
        // return s                                                                           <L 178>
        return var_0;
    }
    // pt = l.portals[k]                                                                      <L 179>
    var_37 = &((var_l).portals);
    var_39 = wp::load(var_37);
    var_38 = wp::address(var_39, var_9);
    var_41 = wp::load(var_38);
    var_40 = wp::copy(var_41);
    // sr = sphrect_setup(p, pt.corner, pt.ex, pt.ey, pt.width, pt.height)                    <L 180>
    var_42 = &((var_40).corner);
    var_43 = &((var_40).ex);
    var_44 = &((var_40).ey);
    var_45 = &((var_40).width);
    var_46 = &((var_40).height);
    var_48 = wp::load(var_42);
    var_49 = wp::load(var_43);
    var_50 = wp::load(var_44);
    var_51 = wp::load(var_45);
    var_52 = wp::load(var_46);
    var_47 = sphrect_setup_0(var_p, var_48, var_49, var_50, var_51, var_52);
    // wi = wp.vec3(0.0, 0.0, 1.0)                                                            <L 181>
    var_56 = wp::vec_t<3, wp::float32>(var_53, var_54, var_55);
    // dens = float(0.0)                                                                      <L 182>
    var_58 = wp::float(var_57);
    // if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:                                           <L 183>
    var_59 = &((var_47).solid_angle);
    var_62 = wp::load(var_59);
    var_61 = (var_62 > var_60);
    if (var_61) {
        // wi = wp.normalize(sphrect_sample(sr, wp.vec2(u[0], u[1])) - p)                     <L 184>
        var_64 = wp::extract(var_u, var_63);
        var_66 = wp::extract(var_u, var_65);
        var_67 = wp::vec_t<2, wp::float32>(var_64, var_66);
        var_68 = sphrect_sample_0(var_47, var_67);
        var_69 = wp::sub(var_68, var_p);
        var_70 = wp::normalize(var_69);
        // dens = 1.0 / sr.solid_angle                                                        <L 185>
        var_72 = &((var_47).solid_angle);
        var_74 = wp::load(var_72);
        var_73 = wp::div(var_71, var_74);
    }
    if (!var_61) {
        // q = pt.corner + (u[0] * pt.width) * pt.ex + (u[1] * pt.height) * pt.ey             <L 187>
        var_75 = &((var_40).corner);
        var_77 = wp::extract(var_u, var_76);
        var_78 = &((var_40).width);
        var_80 = wp::load(var_78);
        var_79 = wp::mul(var_77, var_80);
        var_81 = &((var_40).ex);
        var_83 = wp::load(var_81);
        var_82 = wp::mul(var_79, var_83);
        var_85 = wp::load(var_75);
        var_84 = wp::add(var_85, var_82);
        var_87 = wp::extract(var_u, var_86);
        var_88 = &((var_40).height);
        var_90 = wp::load(var_88);
        var_89 = wp::mul(var_87, var_90);
        var_91 = &((var_40).ey);
        var_93 = wp::load(var_91);
        var_92 = wp::mul(var_89, var_93);
        var_94 = wp::add(var_84, var_92);
        // d = q - p                                                                          <L 188>
        var_95 = wp::sub(var_94, var_p);
        // dist = wp.length(d)                                                                <L 189>
        var_96 = wp::length(var_95);
        // if dist <= 0.0:                                                                    <L 190>
        var_98 = (var_96 <= var_97);
        if (var_98) {
            // return s                                                                       <L 191>
            return var_0;
        }
        // wi = d / dist                                                                      <L 192>
        var_99 = wp::div(var_95, var_96);
        // cos_l = wp.dot(wi, pt.ez)                                                          <L 193>
        var_100 = &((var_40).ez);
        var_102 = wp::load(var_100);
        var_101 = wp::dot(var_99, var_102);
        // if cos_l <= 0.0:                                                                   <L 194>
        var_104 = (var_101 <= var_103);
        if (var_104) {
            // return s                                                                       <L 195>
            return var_0;
        }
        // dens = dist * dist / (pt.width * pt.height * cos_l)                                <L 196>
        var_105 = wp::mul(var_96, var_96);
        var_106 = &((var_40).width);
        var_107 = &((var_40).height);
        var_109 = wp::load(var_106);
        var_110 = wp::load(var_107);
        var_108 = wp::mul(var_109, var_110);
        var_111 = wp::mul(var_108, var_101);
        var_112 = wp::div(var_105, var_111);
    }
    var_113 = wp::where(var_61, var_70, var_99);
    var_114 = wp::where(var_61, var_73, var_112);
    // pdf_w = (wk / total) * dens                                                            <L 197>
    var_115 = wp::div(var_11, var_total);
    var_116 = wp::mul(var_115, var_114);
    // if not single:                                                                         <L 198>
    var_117 = wp::unot(var_3);
    if (var_117) {
        // pdf_w += pdf_portals(l, p, n, wi, total, k)                                        <L 199>
        var_118 = pdf_portals_0(var_l, var_p, var_n, var_113, var_total, var_9);
        var_119 = wp::add(var_116, var_118);
    }
    var_120 = wp::where(var_117, var_119, var_116);
    // s.wi = wi                                                                              <L 200>
    var_0.wi = var_113;
    // s.dist = RAY_INF                                                                       <L 201>
    var_0.dist = var_121;
    // s.pdf = pdf_w                                                                          <L 202>
    var_0.pdf = var_120;
    // cos_r = wp.dot(wi, n)                                                                  <L 203>
    var_122 = wp::dot(var_113, var_n);
    // if cos_r > 0.0:                                                                        <L 204>
    var_124 = (var_122 > var_123);
    if (var_124) {
        // s.value = escaped(l, wi) * (cos_r / pdf_w)                                         <L 205>
        var_125 = escaped_1(var_l, var_113);
        var_126 = wp::div(var_122, var_120);
        var_127 = wp::mul(var_125, var_126);
        var_0.value = var_127;
    }
    // return s                                                                               <L 206>
    return var_0;
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


// /work/main/simulator/kernels/lights/dome.py:50
static LightSample_1981fb4b sample_map_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::array_t<wp::float32>* var_1;
    wp::array_t<wp::float32>* var_2;
    wp::int32* var_3;
    wp::int32* var_4;
    wp::vec_t<3, wp::float32>* var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32>* var_7;
    const wp::int32 var_8 = 0;
    wp::float32 var_9;
    const wp::int32 var_10 = 1;
    wp::float32 var_11;
    wp::vec_t<2, wp::float32> var_12;
    LatLongSample_6aa5dbc2 var_13;
    wp::array_t<wp::float32> var_14;
    wp::array_t<wp::float32> var_15;
    wp::int32 var_16;
    wp::int32 var_17;
    wp::vec_t<3, wp::float32> var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::float32* var_21;
    const wp::float32 var_22 = 0.0;
    bool var_23;
    wp::float32 var_24;
    wp::vec_t<3, wp::float32>* var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::vec_t<3, wp::float32> var_27;
    const wp::float32 var_28 = 1e+30;
    wp::float32* var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    wp::vec_t<3, wp::float32>* var_32;
    wp::float32 var_33;
    wp::vec_t<3, wp::float32> var_34;
    const wp::float32 var_35 = 0.0;
    bool var_36;
    wp::vec_t<2, wp::float32>* var_37;
    wp::array_t<wp::float32>* var_38;
    wp::int32* var_39;
    wp::int32 var_40;
    wp::float32* var_41;
    wp::array_t<wp::float32> var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32* var_45;
    wp::float32 var_46;
    wp::float32 var_47;
    wp::vec_t<2, wp::float32> var_48;
    wp::vec_t<2, wp::float32> var_49;
    //---------
    // forward
    // def sample_map(l: LightRec, n: wp.vec3, u: wp.vec3) -> LightSample:                    <L 51>
    // s = empty_sample()                                                                     <L 54>
    var_0 = empty_sample_0();
    // ms = sample_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wp.vec2(u[0], u[1]))       <L 55>
    var_1 = &((var_l).map_marg);
    var_2 = &((var_l).map_cond);
    var_3 = &((var_l).map_w);
    var_4 = &((var_l).map_h);
    var_5 = &((var_l).ex);
    var_6 = &((var_l).ey);
    var_7 = &((var_l).ez);
    var_9 = wp::extract(var_u, var_8);
    var_11 = wp::extract(var_u, var_10);
    var_12 = wp::vec_t<2, wp::float32>(var_9, var_11);
    var_14 = wp::load(var_1);
    var_15 = wp::load(var_2);
    var_16 = wp::load(var_3);
    var_17 = wp::load(var_4);
    var_18 = wp::load(var_5);
    var_19 = wp::load(var_6);
    var_20 = wp::load(var_7);
    var_13 = sample_latlong_0(var_14, var_15, var_16, var_17, var_18, var_19, var_20, var_12);
    // if ms.pdf <= 0.0:                                                                      <L 56>
    var_21 = &((var_13).pdf);
    var_24 = wp::load(var_21);
    var_23 = (var_24 <= var_22);
    if (var_23) {
        // return s                                                                           <L 57>
        return var_0;
    }
    // s.wi = ms.wi                                                                           <L 58>
    var_25 = &((var_13).wi);
    var_27 = wp::load(var_25);
    var_26 = wp::copy(var_27);
    var_0.wi = var_26;
    // s.dist = RAY_INF                                                                       <L 59>
    var_0.dist = var_28;
    // s.pdf = ms.pdf                                                                         <L 60>
    var_29 = &((var_13).pdf);
    var_31 = wp::load(var_29);
    var_30 = wp::copy(var_31);
    var_0.pdf = var_30;
    // cos_r = wp.dot(ms.wi, n)                                                               <L 61>
    var_32 = &((var_13).wi);
    var_34 = wp::load(var_32);
    var_33 = wp::dot(var_34, var_n);
    // if cos_r > 0.0:                                                                        <L 62>
    var_36 = (var_33 > var_35);
    if (var_36) {
        // s.value = l.emission * (l.map[ms.texel] * cos_r / ms.pdf)                          <L 63>
        var_37 = &((var_l).emission);
        var_38 = &((var_l).map);
        var_39 = &((var_13).texel);
        var_40 = wp::load(var_39);
        var_42 = wp::load(var_38);
        var_41 = wp::address(var_42, var_40);
        var_44 = wp::load(var_41);
        var_43 = wp::mul(var_44, var_33);
        var_45 = &((var_13).pdf);
        var_47 = wp::load(var_45);
        var_46 = wp::div(var_43, var_47);
        var_49 = wp::load(var_37);
        var_48 = wp::mul(var_49, var_46);
        var_0.value = var_48;
    }
    // return s                                                                               <L 64>
    return var_0;
}


// /work/main/simulator/kernels/sampling.py:117
static wp::vec_t<3, wp::float32> sample_cosine_hemisphere_0(
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::vec_t<2, wp::float32> var_0;
    const wp::float32 var_1 = 0.0;
    const wp::float32 var_2 = 1.0;
    const wp::int32 var_3 = 0;
    wp::float32 var_4;
    const wp::int32 var_5 = 0;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    const wp::int32 var_9 = 1;
    wp::float32 var_10;
    const wp::int32 var_11 = 1;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::float32 var_16;
    const wp::int32 var_17 = 0;
    wp::float32 var_18;
    const wp::int32 var_19 = 1;
    wp::float32 var_20;
    wp::vec_t<3, wp::float32> var_21;
    //---------
    // forward
    // def sample_cosine_hemisphere(u: wp.vec2) -> wp.vec3:                                   <L 118>
    // d = sample_concentric_disk(u)                                                          <L 120>
    var_0 = sample_concentric_disk_0(var_u);
    // z = wp.sqrt(wp.max(0.0, 1.0 - d[0] * d[0] - d[1] * d[1]))                              <L 121>
    var_4 = wp::extract(var_0, var_3);
    var_6 = wp::extract(var_0, var_5);
    var_7 = wp::mul(var_4, var_6);
    var_8 = wp::sub(var_2, var_7);
    var_10 = wp::extract(var_0, var_9);
    var_12 = wp::extract(var_0, var_11);
    var_13 = wp::mul(var_10, var_12);
    var_14 = wp::sub(var_8, var_13);
    var_15 = wp::max(var_1, var_14);
    var_16 = wp::sqrt(var_15);
    // return wp.vec3(d[0], d[1], z)                                                          <L 122>
    var_18 = wp::extract(var_0, var_17);
    var_20 = wp::extract(var_0, var_19);
    var_21 = wp::vec_t<3, wp::float32>(var_18, var_20, var_16);
    return var_21;
}


// /work/main/simulator/kernels/sampling.py:125
static wp::float32 pdf_cosine_hemisphere_0(
    wp::float32 var_cos_theta)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    bool var_1;
    const wp::float32 var_2 = 0.3183098861837907;
    wp::float32 var_3;
    const wp::float32 var_4 = 0.0;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_cosine_hemisphere(cos_theta: float) -> float:                                  <L 126>
    // return wp.where(cos_theta > 0.0, cos_theta * INV_PI, 0.0)                              <L 127>
    var_1 = (var_cos_theta > var_0);
    var_3 = wp::mul(var_cos_theta, var_2);
    var_5 = wp::where(var_1, var_3, var_4);
    return var_5;
}


// /work/main/simulator/kernels/lights/dome.py:212
static LightSample_1981fb4b sample_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::int32* var_1;
    const wp::int32 var_2 = 0;
    bool var_3;
    wp::int32 var_4;
    wp::float32 var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    LightSample_1981fb4b var_8;
    wp::int32* var_9;
    const wp::int32 var_10 = 0;
    bool var_11;
    wp::int32 var_12;
    LightSample_1981fb4b var_13;
    const wp::int32 var_14 = 0;
    wp::float32 var_15;
    const wp::int32 var_16 = 1;
    wp::float32 var_17;
    wp::vec_t<2, wp::float32> var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32> var_20;
    const wp::float32 var_21 = 1e+30;
    const wp::int32 var_22 = 2;
    wp::float32 var_23;
    wp::float32 var_24;
    wp::float32* var_25;
    const wp::float32 var_26 = 0.0;
    bool var_27;
    wp::float32 var_28;
    wp::vec_t<2, wp::float32>* var_29;
    const wp::float32 var_30 = 3.141592653589793;
    wp::vec_t<2, wp::float32> var_31;
    wp::vec_t<2, wp::float32> var_32;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 213>
    // s = empty_sample()                                                                     <L 214>
    var_0 = empty_sample_0();
    // if l.n_portals > 0:                                                                    <L 215>
    var_1 = &((var_l).n_portals);
    var_4 = wp::load(var_1);
    var_3 = (var_4 > var_2);
    if (var_3) {
        // total = portals_total(l, p, n)                                                     <L 216>
        var_5 = portals_total_0(var_l, var_p, var_n);
        // if total > 0.0:                                                                    <L 217>
        var_7 = (var_5 > var_6);
        if (var_7) {
            // return sample_portals(l, p, n, u, total)                                       <L 218>
            var_8 = sample_portals_0(var_l, var_p, var_n, var_u, var_5);
            return var_8;
        }
    }
    // if l.has_map != 0:                                                                     <L 219>
    var_9 = &((var_l).has_map);
    var_12 = wp::load(var_9);
    var_11 = (var_12 != var_10);
    if (var_11) {
        // return sample_map(l, n, u)                                                         <L 220>
        var_13 = sample_map_0(var_l, var_n, var_u);
        return var_13;
    }
    // local = sample_cosine_hemisphere(wp.vec2(u[0], u[1]))                                  <L 221>
    var_15 = wp::extract(var_u, var_14);
    var_17 = wp::extract(var_u, var_16);
    var_18 = wp::vec_t<2, wp::float32>(var_15, var_17);
    var_19 = sample_cosine_hemisphere_0(var_18);
    // s.wi = to_world(local, n)                                                              <L 222>
    var_20 = to_world_0(var_19, var_n);
    var_0.wi = var_20;
    // s.dist = RAY_INF                                                                       <L 223>
    var_0.dist = var_21;
    // s.pdf = pdf_cosine_hemisphere(local[2])                                                <L 224>
    var_23 = wp::extract(var_19, var_22);
    var_24 = pdf_cosine_hemisphere_0(var_23);
    var_0.pdf = var_24;
    // if s.pdf > 0.0:                                                                        <L 225>
    var_25 = &((var_0).pdf);
    var_28 = wp::load(var_25);
    var_27 = (var_28 > var_26);
    if (var_27) {
        // s.value = l.emission * PI  # L·cosθ / (cosθ/π)                                     <L 226>
        var_29 = &((var_l).emission);
        var_32 = wp::load(var_29);
        var_31 = wp::mul(var_32, var_30);
        var_0.value = var_31;
    }
    // return s                                                                               <L 227>
    return var_0;
}


// /work/main/simulator/kernels/lights/cylinder.py:27
static LightSample_1981fb4b sample_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 6.283185307179586;
    const wp::int32 var_1 = 1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32>* var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::float32 var_8;
    wp::vec_t<3, wp::float32>* var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<3, wp::float32> var_11;
    wp::vec_t<3, wp::float32> var_12;
    wp::vec_t<3, wp::float32>* var_13;
    const wp::int32 var_14 = 0;
    wp::float32 var_15;
    const wp::float32 var_16 = 0.5;
    wp::float32 var_17;
    wp::float32* var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::vec_t<3, wp::float32>* var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32> var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::float32* var_26;
    wp::vec_t<3, wp::float32> var_27;
    wp::float32 var_28;
    wp::vec_t<3, wp::float32> var_29;
    LightSample_1981fb4b var_30;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 28>
    // phi = TWO_PI * u[1]                                                                    <L 32>
    var_2 = wp::extract(var_u, var_1);
    var_3 = wp::mul(var_0, var_2);
    // nl = wp.cos(phi) * l.ey + wp.sin(phi) * l.ez                                           <L 33>
    var_4 = wp::cos(var_3);
    var_5 = &((var_l).ey);
    var_7 = wp::load(var_5);
    var_6 = wp::mul(var_4, var_7);
    var_8 = wp::sin(var_3);
    var_9 = &((var_l).ez);
    var_11 = wp::load(var_9);
    var_10 = wp::mul(var_8, var_11);
    var_12 = wp::add(var_6, var_10);
    // return area_sample(l, p, n, l.position + ((u[0] - 0.5) * l.length) * l.ex + l.radius * nl, nl)       <L 34>
    var_13 = &((var_l).position);
    var_15 = wp::extract(var_u, var_14);
    var_17 = wp::sub(var_15, var_16);
    var_18 = &((var_l).length);
    var_20 = wp::load(var_18);
    var_19 = wp::mul(var_17, var_20);
    var_21 = &((var_l).ex);
    var_23 = wp::load(var_21);
    var_22 = wp::mul(var_19, var_23);
    var_25 = wp::load(var_13);
    var_24 = wp::add(var_25, var_22);
    var_26 = &((var_l).radius);
    var_28 = wp::load(var_26);
    var_27 = wp::mul(var_28, var_12);
    var_29 = wp::add(var_24, var_27);
    var_30 = area_sample_0(var_l, var_p, var_n, var_29, var_12);
    return var_30;
}


// /work/main/simulator/kernels/lights/emissive.py:34
static wp::vec_t<2, wp::float32> piece_estimate_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::array_t<wp::vec_t<4, wp::float32>>* var_0;
    wp::vec_t<4, wp::float32>* var_1;
    wp::array_t<wp::vec_t<4, wp::float32>> var_2;
    wp::vec_t<4, wp::float32> var_3;
    wp::vec_t<4, wp::float32> var_4;
    wp::array_t<wp::vec_t<3, wp::float32>>* var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::array_t<wp::vec_t<3, wp::float32>> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 3.14159265358979;
    const wp::int32 var_12 = 1;
    wp::float32 var_13;
    wp::float32 var_14;
    const wp::float32 var_15 = 0.0;
    bool var_16;
    const wp::float32 var_17 = 1.0;
    wp::vec_t<2, wp::float32> var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    const wp::int32 var_21 = 2;
    wp::float32 var_22;
    wp::float32 var_23;
    const wp::float32 var_24 = -1e-06;
    wp::float32 var_25;
    bool var_26;
    const wp::float32 var_27 = 0.0;
    const wp::float32 var_28 = 0.0;
    wp::vec_t<2, wp::float32> var_29;
    const wp::int32 var_30 = 2;
    wp::float32 var_31;
    wp::float32 var_32;
    const wp::int32 var_33 = 2;
    wp::float32 var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    const wp::float32 var_37 = 0.0;
    const wp::float32 var_38 = 1.0;
    wp::float32 var_39;
    wp::array_t<wp::vec_t<3, wp::float32>>* var_40;
    wp::vec_t<3, wp::float32>* var_41;
    wp::array_t<wp::vec_t<3, wp::float32>> var_42;
    wp::vec_t<3, wp::float32> var_43;
    wp::vec_t<3, wp::float32> var_44;
    wp::float32 var_45;
    wp::float32 var_46;
    wp::float32 var_47;
    wp::float32 var_48;
    const wp::int32 var_49 = 3;
    wp::float32 var_50;
    const wp::float32 var_51 = 0.0;
    bool var_52;
    wp::float32 var_53;
    const wp::float32 var_54 = 0.0;
    wp::float32 var_55;
    wp::float32 var_56;
    const wp::float32 var_57 = 0.5;
    const wp::float32 var_58 = 1.0;
    wp::float32 var_59;
    wp::float32 var_60;
    wp::float32 var_61;
    const wp::int32 var_62 = 1;
    wp::float32 var_63;
    const wp::int32 var_64 = 0;
    wp::float32 var_65;
    wp::float32 var_66;
    wp::float32 var_67;
    wp::float32 var_68;
    wp::float32 var_69;
    wp::float32 var_70;
    const wp::float32 var_71 = 1.0;
    wp::vec_t<2, wp::float32> var_72;
    //---------
    // forward
    // def piece_estimate(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:        <L 35>
    // sh = scene.piece_shape[k]                                                              <L 41>
    var_0 = &((var_scene).piece_shape);
    var_2 = wp::load(var_0);
    var_1 = wp::address(var_2, var_k);
    var_4 = wp::load(var_1);
    var_3 = wp::copy(var_4);
    // d = scene.piece_centre[k] - p                                                          <L 42>
    var_5 = &((var_scene).piece_centre);
    var_7 = wp::load(var_5);
    var_6 = wp::address(var_7, var_k);
    var_9 = wp::load(var_6);
    var_8 = wp::sub(var_9, var_p);
    // d2 = wp.length_sq(d)                                                                   <L 43>
    var_10 = wp::length_sq(var_8);
    // cap = _PI * sh[1]                                                                      <L 44>
    var_13 = wp::extract(var_3, var_12);
    var_14 = wp::mul(var_11, var_13);
    // if d2 <= 0.0:                                                                          <L 45>
    var_16 = (var_10 <= var_15);
    if (var_16) {
        // return wp.vec2(cap, 1.0)                                                           <L 46>
        var_18 = wp::vec_t<2, wp::float32>(var_14, var_17);
        return var_18;
    }
    // dist = wp.sqrt(d2)                                                                     <L 47>
    var_19 = wp::sqrt(var_10);
    // h = wp.dot(d, n)                                                                       <L 48>
    var_20 = wp::dot(var_8, var_n);
    // if h + sh[2] < -1.0e-6 * dist:                                                         <L 49>
    var_22 = wp::extract(var_3, var_21);
    var_23 = wp::add(var_20, var_22);
    var_25 = wp::mul(var_24, var_19);
    var_26 = (var_23 < var_25);
    if (var_26) {
        // return wp.vec2(0.0, 0.0)                                                           <L 50>
        var_29 = wp::vec_t<2, wp::float32>(var_27, var_28);
        return var_29;
    }
    // cos_r = wp.clamp((h + sh[2]) / (dist + sh[2]), 0.0, 1.0)                               <L 51>
    var_31 = wp::extract(var_3, var_30);
    var_32 = wp::add(var_20, var_31);
    var_34 = wp::extract(var_3, var_33);
    var_35 = wp::add(var_19, var_34);
    var_36 = wp::div(var_32, var_35);
    var_39 = wp::clamp(var_36, var_37, var_38);
    // nn = scene.piece_normal[k]                                                             <L 52>
    var_40 = &((var_scene).piece_normal);
    var_42 = wp::load(var_40);
    var_41 = wp::address(var_42, var_k);
    var_44 = wp::load(var_41);
    var_43 = wp::copy(var_44);
    // flat = wp.length(nn)                                                                   <L 53>
    var_45 = wp::length(var_43);
    // s = -wp.dot(d, nn) / dist  # > 0: the receiver is on the front side                    <L 54>
    var_46 = wp::dot(var_8, var_43);
    var_47 = wp::neg(var_46);
    var_48 = wp::div(var_47, var_19);
    // cos_l = wp.where(sh[3] > 0.0, wp.abs(s), wp.max(s, 0.0)) + 0.5 * (1.0 - flat)          <L 55>
    var_50 = wp::extract(var_3, var_49);
    var_52 = (var_50 > var_51);
    var_53 = wp::abs(var_48);
    var_55 = wp::max(var_48, var_54);
    var_56 = wp::where(var_52, var_53, var_55);
    var_59 = wp::sub(var_58, var_45);
    var_60 = wp::mul(var_57, var_59);
    var_61 = wp::add(var_56, var_60);
    // return wp.vec2(wp.min(sh[1] * sh[0] * cos_l * cos_r / d2, cap), 1.0)                   <L 56>
    var_63 = wp::extract(var_3, var_62);
    var_65 = wp::extract(var_3, var_64);
    var_66 = wp::mul(var_63, var_65);
    var_67 = wp::mul(var_66, var_61);
    var_68 = wp::mul(var_67, var_39);
    var_69 = wp::div(var_68, var_10);
    var_70 = wp::min(var_69, var_14);
    var_72 = wp::vec_t<2, wp::float32>(var_70, var_71);
    return var_72;
}


// /work/main/simulator/kernels/lights/emissive.py:59
static wp::vec_t<2, wp::float32> piece_weights_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::vec_t<2, wp::float32> var_0;
    const wp::int32 var_1 = 0;
    wp::float32 var_2;
    wp::array_t<wp::float32>* var_3;
    wp::float32* var_4;
    wp::array_t<wp::float32> var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    const wp::int32 var_8 = 1;
    wp::float32 var_9;
    wp::vec_t<2, wp::float32> var_10;
    //---------
    // forward
    // def piece_weights(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 60>
    // e = piece_estimate(scene, k, p, n)                                                     <L 62>
    var_0 = piece_estimate_0(var_scene, var_k, var_p, var_n);
    // return wp.vec2(e[0] * scene.piece_factor[k], e[1])                                     <L 63>
    var_2 = wp::extract(var_0, var_1);
    var_3 = &((var_scene).piece_factor);
    var_5 = wp::load(var_3);
    var_4 = wp::address(var_5, var_k);
    var_7 = wp::load(var_4);
    var_6 = wp::mul(var_2, var_7);
    var_9 = wp::extract(var_0, var_8);
    var_10 = wp::vec_t<2, wp::float32>(var_6, var_9);
    return var_10;
}


// /work/main/simulator/kernels/lights/emissive.py:66
static wp::vec_t<2, wp::float32> piece_totals_0(
    SceneRec_19d73428 var_scene,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    const wp::float32 var_1 = 0.0;
    wp::vec_t<2, wp::float32> var_2;
    wp::int32* var_3;
    wp::range_t var_4;
    wp::int32 var_5;
    wp::int32 var_6;
    wp::vec_t<2, wp::float32> var_7;
    wp::vec_t<2, wp::float32> var_8;
    //---------
    // forward
    // def piece_totals(scene: SceneRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:                  <L 67>
    // tot = wp.vec2(0.0, 0.0)                                                                <L 69>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    // for k in range(scene.n_pieces):                                                        <L 70>
    var_3 = &((var_scene).n_pieces);
    var_5 = wp::load(var_3);
    var_4 = wp::range(var_5);
    start_for_0:;
        if (iter_cmp(var_4) == 0) goto end_for_0;
        var_6 = wp::iter_next(var_4);
        // tot += piece_weights(scene, k, p, n)                                               <L 71>
        var_7 = piece_weights_0(var_scene, var_6, var_p, var_n);
        var_8 = wp::add(var_2, var_7);
        wp::assign(var_2, var_8);
        goto start_for_0;
    end_for_0:;
    // return tot                                                                             <L 72>
    return var_2;
}


// /work/main/simulator/kernels/lights/emissive.py:75
static wp::float32 piece_probability_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<2, wp::float32> var_tot)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 1;
    bool var_2;
    wp::int32 var_3;
    const wp::float32 var_4 = 1.0;
    wp::vec_t<2, wp::float32> var_5;
    const wp::int32 var_6 = 0;
    wp::float32 var_7;
    const wp::float32 var_8 = 0.0;
    bool var_9;
    const wp::float32 var_10 = 0.1;
    const wp::float32 var_11 = 1.0;
    wp::float32 var_12;
    const wp::float32 var_13 = 0.0;
    wp::float32 var_14;
    const wp::int32 var_15 = 0;
    wp::float32 var_16;
    const wp::float32 var_17 = 0.0;
    bool var_18;
    const wp::float32 var_19 = 1.0;
    wp::float32 var_20;
    const wp::int32 var_21 = 0;
    wp::float32 var_22;
    wp::float32 var_23;
    const wp::int32 var_24 = 0;
    wp::float32 var_25;
    wp::float32 var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    const wp::int32 var_29 = 1;
    wp::float32 var_30;
    const wp::float32 var_31 = 0.0;
    bool var_32;
    const wp::int32 var_33 = 1;
    wp::float32 var_34;
    wp::float32 var_35;
    const wp::int32 var_36 = 1;
    wp::float32 var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    wp::float32 var_40;
    //---------
    // forward
    // def piece_probability(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3, tot: wp.vec2) -> float:       <L 76>
    // if scene.n_pieces <= 1:                                                                <L 78>
    var_0 = &((var_scene).n_pieces);
    var_3 = wp::load(var_0);
    var_2 = (var_3 <= var_1);
    if (var_2) {
        // return 1.0                                                                         <L 79>
        return var_4;
    }
    // wc = piece_weights(scene, k, p, n)                                                     <L 80>
    var_5 = piece_weights_0(var_scene, var_k, var_p, var_n);
    // a = wp.where(tot[0] > 0.0, PIECE_UNIFORM, 1.0)                                         <L 81>
    var_7 = wp::extract(var_tot, var_6);
    var_9 = (var_7 > var_8);
    var_12 = wp::where(var_9, var_10, var_11);
    // prob = float(0.0)                                                                      <L 82>
    var_14 = wp::float(var_13);
    // if tot[0] > 0.0:                                                                       <L 83>
    var_16 = wp::extract(var_tot, var_15);
    var_18 = (var_16 > var_17);
    if (var_18) {
        // prob += (1.0 - a) * wc[0] / tot[0]                                                 <L 84>
        var_20 = wp::sub(var_19, var_12);
        var_22 = wp::extract(var_5, var_21);
        var_23 = wp::mul(var_20, var_22);
        var_25 = wp::extract(var_tot, var_24);
        var_26 = wp::div(var_23, var_25);
        var_27 = wp::add(var_14, var_26);
    }
    var_28 = wp::where(var_18, var_27, var_14);
    // if tot[1] > 0.0:                                                                       <L 85>
    var_30 = wp::extract(var_tot, var_29);
    var_32 = (var_30 > var_31);
    if (var_32) {
        // prob += a * wc[1] / tot[1]                                                         <L 86>
        var_34 = wp::extract(var_5, var_33);
        var_35 = wp::mul(var_12, var_34);
        var_37 = wp::extract(var_tot, var_36);
        var_38 = wp::div(var_35, var_37);
        var_39 = wp::add(var_28, var_38);
    }
    var_40 = wp::where(var_32, var_39, var_28);
    // return prob                                                                            <L 87>
    return var_40;
}


// /work/main/simulator/kernels/lights/emissive.py:97
static PiecePick_dedfee88 pick_piece_0(
    SceneRec_19d73428 var_scene,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::float32 var_u)
{
    //---------
    // primal vars
    PiecePick_dedfee88 var_0;
    const wp::int32 var_1 = 0;
    const wp::float32 var_2 = 1.0;
    wp::int32* var_3;
    const wp::int32 var_4 = 1;
    bool var_5;
    wp::int32 var_6;
    wp::vec_t<2, wp::float32> var_7;
    const wp::int32 var_8 = -1;
    const wp::int32 var_9 = 1;
    wp::float32 var_10;
    const wp::float32 var_11 = 0.0;
    bool var_12;
    const wp::float32 var_13 = 0.0;
    wp::float32 var_14;
    const wp::int32 var_15 = -1;
    wp::int32 var_16;
    wp::int32* var_17;
    wp::range_t var_18;
    wp::int32 var_19;
    wp::int32 var_20;
    wp::float32 var_21;
    const wp::float32 var_22 = 0.0;
    bool var_23;
    wp::int32 var_24;
    wp::float32 var_25;
    bool var_26;
    wp::float32 var_27;
    wp::float32 var_28;
    const wp::float32 var_29 = 0.0;
    const wp::float32 var_30 = 0.99999994;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::float32 var_33;
    wp::int32 var_34;
    const wp::int32 var_35 = 0;
    bool var_36;
    wp::float32 var_37;
    const wp::float32 var_38 = 0.99999994;
    //---------
    // forward
    // def pick_piece(scene: SceneRec, p: wp.vec3, n: wp.vec3, u: float) -> PiecePick:        <L 98>
    // pk = PiecePick()                                                                       <L 102>
    var_0 = PiecePick_dedfee88();
    // pk.k = 0                                                                               <L 103>
    var_0.k = var_1;
    // pk.prob = 1.0                                                                          <L 104>
    var_0.prob = var_2;
    // pk.u = u                                                                               <L 105>
    var_0.u = var_u;
    // if scene.n_pieces <= 1:                                                                <L 106>
    var_3 = &((var_scene).n_pieces);
    var_6 = wp::load(var_3);
    var_5 = (var_6 <= var_4);
    if (var_5) {
        // return pk                                                                          <L 107>
        return var_0;
    }
    // tot = piece_totals(scene, p, n)                                                        <L 108>
    var_7 = piece_totals_0(var_scene, var_p, var_n);
    // pk.k = -1                                                                              <L 109>
    var_0.k = var_8;
    // if tot[1] <= 0.0:                                                                      <L 110>
    var_10 = wp::extract(var_7, var_9);
    var_12 = (var_10 <= var_11);
    if (var_12) {
        // return pk                                                                          <L 111>
        return var_0;
    }
    // run = float(0.0)                                                                       <L 112>
    var_14 = wp::float(var_13);
    // last = int(-1)                                                                         <L 113>
    var_16 = wp::int(var_15);
    // for k in range(scene.n_pieces):                                                        <L 114>
    var_17 = &((var_scene).n_pieces);
    var_19 = wp::load(var_17);
    var_18 = wp::range(var_19);
    start_for_2:;
        if (iter_cmp(var_18) == 0) goto end_for_2;
        var_20 = wp::iter_next(var_18);
        // pr = piece_probability(scene, k, p, n, tot)                                        <L 115>
        var_21 = piece_probability_0(var_scene, var_20, var_p, var_n, var_7);
        // if pr > 0.0:                                                                       <L 116>
        var_23 = (var_21 > var_22);
        if (var_23) {
            // last = k                                                                       <L 117>
            var_24 = wp::copy(var_20);
            // if u < run + pr:                                                               <L 118>
            var_25 = wp::add(var_14, var_21);
            var_26 = (var_u < var_25);
            if (var_26) {
                // pk.k = k                                                                   <L 119>
                var_0.k = var_20;
                // pk.prob = pr                                                               <L 120>
                var_0.prob = var_21;
                // pk.u = wp.clamp((u - run) / pr, 0.0, 0.99999994)                           <L 121>
                var_27 = wp::sub(var_u, var_14);
                var_28 = wp::div(var_27, var_21);
                var_31 = wp::clamp(var_28, var_29, var_30);
                var_0.u = var_31;
                // return pk                                                                  <L 122>
                return var_0;
            }
            // run += pr                                                                      <L 123>
            var_32 = wp::add(var_14, var_21);
        }
        var_33 = wp::where(var_23, var_32, var_14);
        var_34 = wp::where(var_23, var_24, var_16);
        wp::assign(var_14, var_33);
        wp::assign(var_16, var_34);
        goto start_for_2;
    end_for_2:;
    // if last >= 0:  # u past the float32 sum of the probabilities: the last piece with any       <L 124>
    var_36 = (var_16 >= var_35);
    if (var_36) {
        // pk.k = last                                                                        <L 125>
        var_0.k = var_16;
        // pk.prob = piece_probability(scene, last, p, n, tot)                                <L 126>
        var_37 = piece_probability_0(var_scene, var_16, var_p, var_n, var_7);
        var_0.prob = var_37;
        // pk.u = 0.99999994                                                                  <L 127>
        var_0.u = var_38;
    }
    // return pk                                                                              <L 128>
    return var_0;
}


// /work/main/simulator/kernels/lights/emissive.py:131
static wp::int32 pick_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::float32 var_u)
{
    //---------
    // primal vars
    wp::array_t<wp::int32>* var_0;
    wp::int32* var_1;
    wp::array_t<wp::int32> var_2;
    wp::int32 var_3;
    wp::int32 var_4;
    wp::array_t<wp::int32>* var_5;
    wp::int32* var_6;
    wp::array_t<wp::int32> var_7;
    wp::int32 var_8;
    wp::int32 var_9;
    const wp::int32 var_10 = 1;
    wp::int32 var_11;
    bool var_12;
    wp::int32 var_13;
    const wp::int32 var_14 = 2;
    wp::int32 var_15;
    wp::array_t<wp::float32>* var_16;
    wp::float32* var_17;
    wp::array_t<wp::float32> var_18;
    bool var_19;
    wp::float32 var_20;
    const wp::int32 var_21 = 1;
    wp::int32 var_22;
    wp::int32 var_23;
    wp::int32 var_24;
    wp::int32 var_25;
    //---------
    // forward
    // def pick(scene: SceneRec, k: int, u: float) -> int:                                    <L 132>
    // lo = scene.piece_first[k]                                                              <L 135>
    var_0 = &((var_scene).piece_first);
    var_2 = wp::load(var_0);
    var_1 = wp::address(var_2, var_k);
    var_4 = wp::load(var_1);
    var_3 = wp::copy(var_4);
    // hi = lo + scene.piece_count[k] - 1                                                     <L 136>
    var_5 = &((var_scene).piece_count);
    var_7 = wp::load(var_5);
    var_6 = wp::address(var_7, var_k);
    var_9 = wp::load(var_6);
    var_8 = wp::add(var_3, var_9);
    var_11 = wp::sub(var_8, var_10);
    // while lo < hi:                                                                         <L 137>
    start_while_0:;
    var_12 = (var_3 < var_11);
    if ((var_12) == false) goto end_while_0;
        // mid = (lo + hi) // 2                                                               <L 138>
        var_13 = wp::add(var_3, var_11);
        var_15 = wp::floordiv(var_13, var_14);
        // if scene.emit_cdf[mid] <= u:                                                       <L 139>
        var_16 = &((var_scene).emit_cdf);
        var_18 = wp::load(var_16);
        var_17 = wp::address(var_18, var_15);
        var_20 = wp::load(var_17);
        var_19 = (var_20 <= var_u);
        if (var_19) {
            // lo = mid + 1                                                                   <L 140>
            var_22 = wp::add(var_15, var_21);
        }
        if (!var_19) {
            // hi = mid                                                                       <L 142>
            var_23 = wp::copy(var_15);
        }
        var_24 = wp::where(var_19, var_22, var_3);
        var_25 = wp::where(var_19, var_11, var_23);
        wp::assign(var_3, var_24);
        wp::assign(var_11, var_25);
    goto start_while_0;
    end_while_0:;
    // return lo                                                                              <L 143>
    return var_3;
}


// /work/main/simulator/kernels/lights/base.py:228
static wp::vec_t<3, wp::float32> tri_vertex_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_tri,
    wp::int32 var_k)
{
    //---------
    // primal vars
    wp::array_t<wp::vec_t<3, wp::float32>>* var_0;
    wp::array_t<wp::int32>* var_1;
    const wp::int32 var_2 = 3;
    wp::int32 var_3;
    wp::int32 var_4;
    wp::int32* var_5;
    wp::array_t<wp::int32> var_6;
    wp::int32 var_7;
    wp::vec_t<3, wp::float32>* var_8;
    wp::array_t<wp::vec_t<3, wp::float32>> var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<3, wp::float32> var_11;
    //---------
    // forward
    // def tri_vertex(scene: SceneRec, tri: int, k: int) -> wp.vec3:                          <L 229>
    // return scene.points[scene.tris[3 * tri + k]]                                           <L 230>
    var_0 = &((var_scene).points);
    var_1 = &((var_scene).tris);
    var_3 = wp::mul(var_2, var_tri);
    var_4 = wp::add(var_3, var_k);
    var_6 = wp::load(var_1);
    var_5 = wp::address(var_6, var_4);
    var_7 = wp::load(var_5);
    var_9 = wp::load(var_0);
    var_8 = wp::address(var_9, var_7);
    var_11 = wp::load(var_8);
    var_10 = wp::copy(var_11);
    return var_10;
}


// /work/main/simulator/kernels/sampling.py:164
static wp::vec_t<2, wp::float32> sample_triangle_bary_0(
    wp::vec_t<2, wp::float32> var_u)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::float32 var_1;
    wp::float32 var_2;
    const wp::int32 var_3 = 1;
    wp::float32 var_4;
    wp::float32 var_5;
    const wp::float32 var_6 = 1.0;
    wp::float32 var_7;
    wp::vec_t<2, wp::float32> var_8;
    //---------
    // forward
    // def sample_triangle_bary(u: wp.vec2) -> wp.vec2:                                       <L 165>
    // su = wp.sqrt(u[0])                                                                     <L 167>
    var_1 = wp::extract(var_u, var_0);
    var_2 = wp::sqrt(var_1);
    // return wp.vec2(u[1] * su, 1.0 - su)                                                    <L 168>
    var_4 = wp::extract(var_u, var_3);
    var_5 = wp::mul(var_4, var_2);
    var_7 = wp::sub(var_6, var_2);
    var_8 = wp::vec_t<2, wp::float32>(var_5, var_7);
    return var_8;
}


// /work/main/simulator/kernels/lights/base.py:252
static wp::vec_t<2, wp::float32> tri_emitted_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_tri,
    wp::float32 var_wo_dot_ng)
{
    //---------
    // primal vars
    bool var_0;
    const wp::float32 var_1 = 0.0;
    bool var_2;
    wp::array_t<wp::int32>* var_3;
    wp::int32* var_4;
    wp::array_t<wp::int32> var_5;
    const wp::int32 var_6 = 0;
    bool var_7;
    wp::int32 var_8;
    wp::array_t<wp::vec_t<2, wp::float32>>* var_9;
    wp::vec_t<2, wp::float32>* var_10;
    wp::array_t<wp::vec_t<2, wp::float32>> var_11;
    wp::vec_t<2, wp::float32> var_12;
    wp::vec_t<2, wp::float32> var_13;
    const wp::float32 var_14 = 0.0;
    const wp::float32 var_15 = 0.0;
    wp::vec_t<2, wp::float32> var_16;
    //---------
    // forward
    // def tri_emitted(scene: SceneRec, tri: int, wo_dot_ng: float) -> wp.vec2:               <L 253>
    // if wo_dot_ng > 0.0 or scene.two_sided[tri] != 0:                                       <L 256>
    var_2 = (var_wo_dot_ng > var_1);
    var_0 = var_2;
    if (!var_0) {
        var_3 = &((var_scene).two_sided);
        var_5 = wp::load(var_3);
        var_4 = wp::address(var_5, var_tri);
        var_8 = wp::load(var_4);
        var_7 = (var_8 != var_6);
        var_0 = var_0 || var_7;
    }
    if (var_0) {
        // return scene.emission[tri]                                                         <L 257>
        var_9 = &((var_scene).emission);
        var_11 = wp::load(var_9);
        var_10 = wp::address(var_11, var_tri);
        var_13 = wp::load(var_10);
        var_12 = wp::copy(var_13);
        return var_12;
    }
    // return wp.vec2(0.0, 0.0)                                                               <L 258>
    var_16 = wp::vec_t<2, wp::float32>(var_14, var_15);
    return var_16;
}


// /work/main/simulator/kernels/lights/emissive.py:146
static LightSample_1981fb4b sample_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    wp::array_t<wp::int32>* var_1;
    wp::shape_t* var_2;
    const wp::int32 var_3 = 0;
    wp::int32 var_4;
    wp::shape_t var_5;
    const wp::int32 var_6 = 0;
    bool var_7;
    const wp::int32 var_8 = 0;
    wp::float32 var_9;
    PiecePick_dedfee88 var_10;
    wp::int32* var_11;
    const wp::int32 var_12 = 0;
    bool var_13;
    wp::int32 var_14;
    wp::array_t<wp::int32>* var_15;
    wp::int32* var_16;
    wp::float32* var_17;
    wp::int32 var_18;
    wp::int32 var_19;
    wp::float32 var_20;
    wp::int32* var_21;
    wp::array_t<wp::int32> var_22;
    wp::int32 var_23;
    wp::int32 var_24;
    const wp::int32 var_25 = 0;
    wp::vec_t<3, wp::float32> var_26;
    const wp::int32 var_27 = 1;
    wp::vec_t<3, wp::float32> var_28;
    const wp::int32 var_29 = 2;
    wp::vec_t<3, wp::float32> var_30;
    const wp::int32 var_31 = 1;
    wp::float32 var_32;
    const wp::int32 var_33 = 2;
    wp::float32 var_34;
    wp::vec_t<2, wp::float32> var_35;
    wp::vec_t<2, wp::float32> var_36;
    const wp::int32 var_37 = 0;
    wp::float32 var_38;
    wp::vec_t<3, wp::float32> var_39;
    wp::vec_t<3, wp::float32> var_40;
    wp::vec_t<3, wp::float32> var_41;
    const wp::int32 var_42 = 1;
    wp::float32 var_43;
    wp::vec_t<3, wp::float32> var_44;
    wp::vec_t<3, wp::float32> var_45;
    wp::vec_t<3, wp::float32> var_46;
    wp::vec_t<3, wp::float32> var_47;
    wp::vec_t<3, wp::float32> var_48;
    wp::vec_t<3, wp::float32> var_49;
    const wp::float32 var_50 = 0.5;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::vec_t<3, wp::float32> var_53;
    wp::float32 var_54;
    bool var_55;
    const wp::float32 var_56 = 0.0;
    bool var_57;
    const wp::float32 var_58 = 0.0;
    bool var_59;
    wp::vec_t<3, wp::float32> var_60;
    wp::float32 var_61;
    wp::float32 var_62;
    const wp::float32 var_63 = 2.0;
    wp::float32 var_64;
    wp::float32 var_65;
    wp::vec_t<2, wp::float32> var_66;
    wp::float32 var_67;
    const wp::float32 var_68 = 1e-09;
    bool var_69;
    wp::float32* var_70;
    wp::array_t<wp::float32>* var_71;
    wp::float32* var_72;
    wp::array_t<wp::float32> var_73;
    wp::float32 var_74;
    wp::float32 var_75;
    wp::float32 var_76;
    wp::float32 var_77;
    wp::float32 var_78;
    wp::float32 var_79;
    wp::float32 var_80;
    wp::float32 var_81;
    wp::float32 var_82;
    bool var_83;
    const wp::float32 var_84 = 0.0;
    bool var_85;
    wp::float32* var_86;
    const wp::float32 var_87 = 0.0;
    bool var_88;
    wp::float32 var_89;
    wp::float32* var_90;
    wp::float32 var_91;
    wp::float32 var_92;
    wp::vec_t<2, wp::float32> var_93;
    //---------
    // forward
    // def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 147>
    // s = empty_sample()                                                                     <L 148>
    var_0 = empty_sample_0();
    // if scene.emit_tris.shape[0] == 0:                                                      <L 149>
    var_1 = &((var_scene).emit_tris);
    var_2 = &(var_1->shape);
    var_5 = wp::load(var_2);
    var_4 = wp::extract(var_5, var_3);
    var_7 = (var_4 == var_6);
    if (var_7) {
        // return s                                                                           <L 150>
        return var_0;
    }
    // pp = pick_piece(scene, p, n, u[0])                                                     <L 151>
    var_9 = wp::extract(var_u, var_8);
    var_10 = pick_piece_0(var_scene, var_p, var_n, var_9);
    // if pp.k < 0:                                                                           <L 152>
    var_11 = &((var_10).k);
    var_14 = wp::load(var_11);
    var_13 = (var_14 < var_12);
    if (var_13) {
        // return s                                                                           <L 153>
        return var_0;
    }
    // tri = scene.emit_tris[pick(scene, pp.k, pp.u)]                                         <L 154>
    var_15 = &((var_scene).emit_tris);
    var_16 = &((var_10).k);
    var_17 = &((var_10).u);
    var_19 = wp::load(var_16);
    var_20 = wp::load(var_17);
    var_18 = pick_0(var_scene, var_19, var_20);
    var_22 = wp::load(var_15);
    var_21 = wp::address(var_22, var_18);
    var_24 = wp::load(var_21);
    var_23 = wp::copy(var_24);
    // a = tri_vertex(scene, tri, 0)                                                          <L 155>
    var_26 = tri_vertex_0(var_scene, var_23, var_25);
    // b = tri_vertex(scene, tri, 1)                                                          <L 156>
    var_28 = tri_vertex_0(var_scene, var_23, var_27);
    // c = tri_vertex(scene, tri, 2)                                                          <L 157>
    var_30 = tri_vertex_0(var_scene, var_23, var_29);
    // bc = sample_triangle_bary(wp.vec2(u[1], u[2]))                                         <L 158>
    var_32 = wp::extract(var_u, var_31);
    var_34 = wp::extract(var_u, var_33);
    var_35 = wp::vec_t<2, wp::float32>(var_32, var_34);
    var_36 = sample_triangle_bary_0(var_35);
    // q = a + bc[0] * (b - a) + bc[1] * (c - a)                                              <L 159>
    var_38 = wp::extract(var_36, var_37);
    var_39 = wp::sub(var_28, var_26);
    var_40 = wp::mul(var_38, var_39);
    var_41 = wp::add(var_26, var_40);
    var_43 = wp::extract(var_36, var_42);
    var_44 = wp::sub(var_30, var_26);
    var_45 = wp::mul(var_43, var_44);
    var_46 = wp::add(var_41, var_45);
    // ng2 = wp.cross(b - a, c - a)                                                           <L 160>
    var_47 = wp::sub(var_28, var_26);
    var_48 = wp::sub(var_30, var_26);
    var_49 = wp::cross(var_47, var_48);
    // area = 0.5 * wp.length(ng2)                                                            <L 161>
    var_51 = wp::length(var_49);
    var_52 = wp::mul(var_50, var_51);
    // d = q - p                                                                              <L 162>
    var_53 = wp::sub(var_46, var_p);
    // dist = wp.length(d)                                                                    <L 163>
    var_54 = wp::length(var_53);
    // if dist <= 0.0 or area <= 0.0:                                                         <L 164>
    var_57 = (var_54 <= var_56);
    var_55 = var_57;
    if (!var_55) {
        var_59 = (var_52 <= var_58);
        var_55 = var_55 || var_59;
    }
    if (var_55) {
        // return s                                                                           <L 165>
        return var_0;
    }
    // wi = d / dist                                                                          <L 166>
    var_60 = wp::div(var_53, var_54);
    // cos_l = -wp.dot(wi, ng2) / (2.0 * area)  # > 0 when p is in front                      <L 167>
    var_61 = wp::dot(var_60, var_49);
    var_62 = wp::neg(var_61);
    var_64 = wp::mul(var_63, var_52);
    var_65 = wp::div(var_62, var_64);
    // le = tri_emitted(scene, tri, cos_l)                                                    <L 168>
    var_66 = tri_emitted_0(var_scene, var_23, var_65);
    // if wp.abs(cos_l) < 1.0e-9:                                                             <L 169>
    var_67 = wp::abs(var_65);
    var_69 = (var_67 < var_68);
    if (var_69) {
        // return s                                                                           <L 170>
        return var_0;
    }
    // s.wi = wi                                                                              <L 171>
    var_0.wi = var_60;
    // s.dist = dist                                                                          <L 172>
    var_0.dist = var_54;
    // s.tri = tri                                                                            <L 173>
    var_0.tri = var_23;
    // s.pdf = pp.prob * scene.emit_prob[tri] * dist * dist / (area * wp.abs(cos_l))          <L 174>
    var_70 = &((var_10).prob);
    var_71 = &((var_scene).emit_prob);
    var_73 = wp::load(var_71);
    var_72 = wp::address(var_73, var_23);
    var_75 = wp::load(var_70);
    var_76 = wp::load(var_72);
    var_74 = wp::mul(var_75, var_76);
    var_77 = wp::mul(var_74, var_54);
    var_78 = wp::mul(var_77, var_54);
    var_79 = wp::abs(var_65);
    var_80 = wp::mul(var_52, var_79);
    var_81 = wp::div(var_78, var_80);
    var_0.pdf = var_81;
    // cos_r = wp.dot(wi, n)                                                                  <L 175>
    var_82 = wp::dot(var_60, var_n);
    // if cos_r > 0.0 and s.pdf > 0.0:                                                        <L 176>
    var_85 = (var_82 > var_84);
    var_83 = var_85;
    if (var_83) {
        var_86 = &((var_0).pdf);
        var_89 = wp::load(var_86);
        var_88 = (var_89 > var_87);
        var_83 = var_83 && var_88;
    }
    if (var_83) {
        // s.value = le * (cos_r / s.pdf)                                                     <L 177>
        var_90 = &((var_0).pdf);
        var_92 = wp::load(var_90);
        var_91 = wp::div(var_82, var_92);
        var_93 = wp::mul(var_66, var_91);
        var_0.value = var_93;
    }
    // return s                                                                               <L 178>
    return var_0;
}


// /work/main/simulator/kernels/lights/__init__.py:110
static LightSample_1981fb4b _no_sample_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    LightSample_1981fb4b var_0;
    //---------
    // forward
    // def _no_sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 111>
    // return empty_sample()                                                                  <L 112>
    var_0 = empty_sample_0();
    return var_0;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 7;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_4(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _no_sample_0(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 6;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_0(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_0(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 5;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_3(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_1(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 4;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_2(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_2(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 3;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_1(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_3(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 2;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_6(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_4(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 1;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_7(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_5(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:101
static LightSample_1981fb4b _sample_link__locals__sample_kind_7(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    LightSample_1981fb4b var_4;
    LightSample_1981fb4b var_5;
    //---------
    // forward
    // def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 102>
    // if l.kind == wp.static(k):                                                             <L 103>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, u)                                          <L 104>
        var_4 = sample_5(var_scene, var_l, var_p, var_n, var_u);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, u)                                              <L 105>
    var_5 = _sample_link__locals__sample_kind_6(var_scene, var_l, var_p, var_n, var_u);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:216
static LightSample_1981fb4b sample_light_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_li,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u)
{
    //---------
    // primal vars
    wp::array_t<LightRec_73c30c8a>* var_0;
    LightRec_73c30c8a* var_1;
    wp::array_t<LightRec_73c30c8a> var_2;
    LightSample_1981fb4b var_3;
    LightRec_73c30c8a var_4;
    //---------
    // forward
    // def sample_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:       <L 217>
    // return _sample_chain(scene, scene.lights[li], p, n, u)                                 <L 219>
    var_0 = &((var_scene).lights);
    var_2 = wp::load(var_0);
    var_1 = wp::address(var_2, var_li);
    var_4 = wp::load(var_1);
    var_3 = _sample_link__locals__sample_kind_7(var_scene, var_4, var_p, var_n, var_u);
    return var_3;
}


// /work/main/simulator/kernels/lights/sphere.py:50
static wp::float32 pdf_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::float32 var_0;
    const wp::float32 var_1 = 0.0;
    bool var_2;
    wp::float32 var_3;
    const wp::float32 var_4 = 0.0;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 51>
    // omc = cone(l, p)                                                                       <L 52>
    var_0 = cone_0(var_l, var_p);
    // return wp.where(omc > 0.0, pdf_uniform_cone(omc), 0.0)                                 <L 53>
    var_2 = (var_0 > var_1);
    var_3 = pdf_uniform_cone_0(var_0);
    var_5 = wp::where(var_2, var_3, var_4);
    return var_5;
}


// /work/main/simulator/kernels/lights/base.py:284
static wp::float32 area_pdf_0(
    LightRec_73c30c8a var_l,
    wp::float32 var_cos_l,
    wp::float32 var_t)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    bool var_1;
    wp::float32 var_2;
    wp::float32* var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    const wp::float32 var_7 = 0.0;
    wp::float32 var_8;
    //---------
    // forward
    // def area_pdf(l: LightRec, cos_l: float, t: float) -> float:                            <L 285>
    // return wp.where(cos_l > 0.0, t * t / (l.area * cos_l), 0.0)                            <L 288>
    var_1 = (var_cos_l > var_0);
    var_2 = wp::mul(var_t, var_t);
    var_3 = &((var_l).area);
    var_5 = wp::load(var_3);
    var_4 = wp::mul(var_5, var_cos_l);
    var_6 = wp::div(var_2, var_4);
    var_8 = wp::where(var_1, var_6, var_7);
    return var_8;
}


// /work/main/simulator/kernels/lights/rect.py:49
static wp::float32 pdf_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32> var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::vec_t<3, wp::float32>* var_2;
    wp::float32* var_3;
    wp::float32* var_4;
    SphRect_7f5b29ec var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32* var_10;
    const wp::float32 var_11 = 0.0001;
    bool var_12;
    wp::float32 var_13;
    const wp::float32 var_14 = 1.0;
    wp::float32* var_15;
    wp::float32 var_16;
    wp::float32 var_17;
    wp::vec_t<3, wp::float32>* var_18;
    wp::float32 var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::float32 var_21;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 50>
    // sr = sphrect_setup(p, corner(l), l.ex, l.ey, l.width, l.height)                        <L 51>
    var_0 = corner_0(var_l);
    var_1 = &((var_l).ex);
    var_2 = &((var_l).ey);
    var_3 = &((var_l).width);
    var_4 = &((var_l).height);
    var_6 = wp::load(var_1);
    var_7 = wp::load(var_2);
    var_8 = wp::load(var_3);
    var_9 = wp::load(var_4);
    var_5 = sphrect_setup_0(var_p, var_0, var_6, var_7, var_8, var_9);
    // if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:                                           <L 52>
    var_10 = &((var_5).solid_angle);
    var_13 = wp::load(var_10);
    var_12 = (var_13 > var_11);
    if (var_12) {
        // return 1.0 / sr.solid_angle                                                        <L 53>
        var_15 = &((var_5).solid_angle);
        var_17 = wp::load(var_15);
        var_16 = wp::div(var_14, var_17);
        return var_16;
    }
    // return area_pdf(l, wp.dot(wi, l.ez), t)                                                <L 54>
    var_18 = &((var_l).ez);
    var_20 = wp::load(var_18);
    var_19 = wp::dot(var_wi, var_20);
    var_21 = area_pdf_0(var_l, var_19, var_t);
    return var_21;
}


// /work/main/simulator/kernels/lights/disk.py:26
static wp::float32 pdf_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::float32 var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::float32 var_3;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 27>
    // return area_pdf(l, wp.dot(wi, l.ez), t)                                                <L 28>
    var_0 = &((var_l).ez);
    var_2 = wp::load(var_0);
    var_1 = wp::dot(var_wi, var_2);
    var_3 = area_pdf_0(var_l, var_1, var_t);
    return var_3;
}


// /work/main/simulator/kernels/lights/distant.py:37
static wp::float32 pdf_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::float32* var_0;
    const wp::float32 var_1 = 0.0;
    bool var_2;
    wp::float32 var_3;
    wp::float32* var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    const wp::float32 var_7 = 0.0;
    wp::float32 var_8;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 38>
    // return wp.where(l.one_minus_cos > 0.0, pdf_uniform_cone(l.one_minus_cos), 0.0)         <L 39>
    var_0 = &((var_l).one_minus_cos);
    var_3 = wp::load(var_0);
    var_2 = (var_3 > var_1);
    var_4 = &((var_l).one_minus_cos);
    var_6 = wp::load(var_4);
    var_5 = pdf_uniform_cone_0(var_6);
    var_8 = wp::where(var_2, var_5, var_7);
    return var_8;
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


// /work/main/simulator/kernels/lights/dome.py:230
static wp::float32 pdf_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    const wp::float32 var_5 = 0.0;
    bool var_6;
    const wp::int32 var_7 = -1;
    wp::float32 var_8;
    wp::int32* var_9;
    const wp::int32 var_10 = 0;
    bool var_11;
    wp::int32 var_12;
    wp::array_t<wp::float32>* var_13;
    wp::array_t<wp::float32>* var_14;
    wp::int32* var_15;
    wp::int32* var_16;
    wp::vec_t<3, wp::float32>* var_17;
    wp::vec_t<3, wp::float32>* var_18;
    wp::vec_t<3, wp::float32>* var_19;
    wp::float32 var_20;
    wp::array_t<wp::float32> var_21;
    wp::array_t<wp::float32> var_22;
    wp::int32 var_23;
    wp::int32 var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::vec_t<3, wp::float32> var_27;
    wp::float32 var_28;
    wp::float32 var_29;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 231>
    // if l.n_portals > 0:                                                                    <L 232>
    var_0 = &((var_l).n_portals);
    var_3 = wp::load(var_0);
    var_2 = (var_3 > var_1);
    if (var_2) {
        // total = portals_total(l, p, n)                                                     <L 233>
        var_4 = portals_total_0(var_l, var_p, var_n);
        // if total > 0.0:                                                                    <L 234>
        var_6 = (var_4 > var_5);
        if (var_6) {
            // return pdf_portals(l, p, n, wi, total, -1)                                     <L 235>
            var_8 = pdf_portals_0(var_l, var_p, var_n, var_wi, var_4, var_7);
            return var_8;
        }
    }
    // if l.has_map != 0:                                                                     <L 236>
    var_9 = &((var_l).has_map);
    var_12 = wp::load(var_9);
    var_11 = (var_12 != var_10);
    if (var_11) {
        // return pdf_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wi)       <L 237>
        var_13 = &((var_l).map_marg);
        var_14 = &((var_l).map_cond);
        var_15 = &((var_l).map_w);
        var_16 = &((var_l).map_h);
        var_17 = &((var_l).ex);
        var_18 = &((var_l).ey);
        var_19 = &((var_l).ez);
        var_21 = wp::load(var_13);
        var_22 = wp::load(var_14);
        var_23 = wp::load(var_15);
        var_24 = wp::load(var_16);
        var_25 = wp::load(var_17);
        var_26 = wp::load(var_18);
        var_27 = wp::load(var_19);
        var_20 = pdf_latlong_0(var_21, var_22, var_23, var_24, var_25, var_26, var_27, var_wi);
        return var_20;
    }
    // return pdf_cosine_hemisphere(wp.dot(wi, n))                                            <L 238>
    var_28 = wp::dot(var_wi, var_n);
    var_29 = pdf_cosine_hemisphere_0(var_28);
    return var_29;
}


// /work/main/simulator/kernels/lights/cylinder.py:19
static wp::vec_t<3, wp::float32> side_normal_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_q)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32>* var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::vec_t<3, wp::float32> var_10;
    //---------
    // forward
    // def side_normal(l: LightRec, q: wp.vec3) -> wp.vec3:                                   <L 20>
    // r = q - l.position                                                                     <L 22>
    var_0 = &((var_l).position);
    var_2 = wp::load(var_0);
    var_1 = wp::sub(var_q, var_2);
    // r = r - wp.dot(r, l.ex) * l.ex                                                         <L 23>
    var_3 = &((var_l).ex);
    var_5 = wp::load(var_3);
    var_4 = wp::dot(var_1, var_5);
    var_6 = &((var_l).ex);
    var_8 = wp::load(var_6);
    var_7 = wp::mul(var_4, var_8);
    var_9 = wp::sub(var_1, var_7);
    // return wp.normalize(r)                                                                 <L 24>
    var_10 = wp::normalize(var_9);
    return var_10;
}


// /work/main/simulator/kernels/lights/cylinder.py:37
static wp::float32 pdf_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32> var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 38>
    // return area_pdf(l, -wp.dot(wi, side_normal(l, p + t * wi)), t)                         <L 39>
    var_0 = wp::mul(var_t, var_wi);
    var_1 = wp::add(var_p, var_0);
    var_2 = side_normal_0(var_l, var_1);
    var_3 = wp::dot(var_wi, var_2);
    var_4 = wp::neg(var_3);
    var_5 = area_pdf_0(var_l, var_4, var_t);
    return var_5;
}


// /work/main/simulator/kernels/lights/emissive.py:181
static wp::float32 pdf_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::vec_t<3, wp::float32> var_1;
    const wp::int32 var_2 = 1;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<3, wp::float32> var_4;
    const wp::int32 var_5 = 2;
    wp::vec_t<3, wp::float32> var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::vec_t<3, wp::float32> var_8;
    const wp::float32 var_9 = 0.5;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    const wp::float32 var_14 = 2.0;
    wp::float32 var_15;
    wp::float32 var_16;
    const wp::float32 var_17 = 0.0;
    bool var_18;
    const wp::float32 var_19 = 0.0;
    const wp::float32 var_20 = 1.0;
    wp::float32 var_21;
    wp::int32* var_22;
    const wp::int32 var_23 = 1;
    bool var_24;
    wp::int32 var_25;
    wp::array_t<wp::int32>* var_26;
    wp::int32* var_27;
    wp::array_t<wp::int32> var_28;
    wp::int32 var_29;
    wp::int32 var_30;
    const wp::int32 var_31 = 0;
    bool var_32;
    const wp::float32 var_33 = 0.0;
    wp::vec_t<2, wp::float32> var_34;
    wp::float32 var_35;
    wp::float32 var_36;
    wp::array_t<wp::float32>* var_37;
    wp::float32* var_38;
    wp::array_t<wp::float32> var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    wp::float32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    wp::float32 var_45;
    //---------
    // forward
    // def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 182>
    // a = tri_vertex(scene, tri, 0)                                                          <L 183>
    var_1 = tri_vertex_0(var_scene, var_tri, var_0);
    // ng2 = wp.cross(tri_vertex(scene, tri, 1) - a, tri_vertex(scene, tri, 2) - a)           <L 184>
    var_3 = tri_vertex_0(var_scene, var_tri, var_2);
    var_4 = wp::sub(var_3, var_1);
    var_6 = tri_vertex_0(var_scene, var_tri, var_5);
    var_7 = wp::sub(var_6, var_1);
    var_8 = wp::cross(var_4, var_7);
    // area = 0.5 * wp.length(ng2)                                                            <L 185>
    var_10 = wp::length(var_8);
    var_11 = wp::mul(var_9, var_10);
    // cos_l = wp.abs(wp.dot(wi, ng2)) / (2.0 * area)                                         <L 186>
    var_12 = wp::dot(var_wi, var_8);
    var_13 = wp::abs(var_12);
    var_15 = wp::mul(var_14, var_11);
    var_16 = wp::div(var_13, var_15);
    // if cos_l <= 0.0:                                                                       <L 187>
    var_18 = (var_16 <= var_17);
    if (var_18) {
        // return 0.0                                                                         <L 188>
        return var_19;
    }
    // prob = float(1.0)                                                                      <L 189>
    var_21 = wp::float(var_20);
    // if scene.n_pieces > 1:                                                                 <L 190>
    var_22 = &((var_scene).n_pieces);
    var_25 = wp::load(var_22);
    var_24 = (var_25 > var_23);
    if (var_24) {
        // pc = scene.emit_piece[tri]                                                         <L 191>
        var_26 = &((var_scene).emit_piece);
        var_28 = wp::load(var_26);
        var_27 = wp::address(var_28, var_tri);
        var_30 = wp::load(var_27);
        var_29 = wp::copy(var_30);
        // if pc < 0:  # a triangle that emits nothing: no piece, and emit_prob 0 besides       <L 192>
        var_32 = (var_29 < var_31);
        if (var_32) {
            // return 0.0                                                                     <L 193>
            return var_33;
        }
        // prob = piece_probability(scene, pc, p, n, piece_totals(scene, p, n))               <L 194>
        var_34 = piece_totals_0(var_scene, var_p, var_n);
        var_35 = piece_probability_0(var_scene, var_29, var_p, var_n, var_34);
    }
    var_36 = wp::where(var_24, var_35, var_21);
    // return prob * scene.emit_prob[tri] * t * t / (area * cos_l)                            <L 195>
    var_37 = &((var_scene).emit_prob);
    var_39 = wp::load(var_37);
    var_38 = wp::address(var_39, var_tri);
    var_41 = wp::load(var_38);
    var_40 = wp::mul(var_36, var_41);
    var_42 = wp::mul(var_40, var_t);
    var_43 = wp::mul(var_42, var_t);
    var_44 = wp::mul(var_11, var_16);
    var_45 = wp::div(var_43, var_44);
    return var_45;
}


// /work/main/simulator/kernels/lights/__init__.py:125
static wp::float32 _no_pdf_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    //---------
    // forward
    // def _no_pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 126>
    // return 0.0                                                                             <L 127>
    return var_0;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 7;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_4(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _no_pdf_0(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 6;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_0(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _pdf_link__locals__pdf_kind_0(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 5;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_3(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _pdf_link__locals__pdf_kind_1(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 4;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_2(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _pdf_link__locals__pdf_kind_2(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 3;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_1(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _pdf_link__locals__pdf_kind_3(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 2;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_5(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _pdf_link__locals__pdf_kind_4(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:116
static wp::float32 _pdf_link__locals__pdf_kind_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 1;
    bool var_2;
    wp::int32 var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    //---------
    // forward
    // def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 117>
    // if l.kind == wp.static(k):                                                             <L 118>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n, wi, t, tri)                                 <L 119>
        var_4 = pdf_6(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n, wi, t, tri)                                     <L 120>
    var_5 = _pdf_link__locals__pdf_kind_5(var_scene, var_l, var_p, var_n, var_wi, var_t, var_tri);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:222
static wp::float32 pdf_light_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_li,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri)
{
    //---------
    // primal vars
    wp::array_t<LightRec_73c30c8a>* var_0;
    LightRec_73c30c8a* var_1;
    wp::array_t<LightRec_73c30c8a> var_2;
    wp::float32 var_3;
    LightRec_73c30c8a var_4;
    //---------
    // forward
    // def pdf_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:       <L 223>
    // return _pdf_chain(scene, scene.lights[li], p, n, wi, t, tri)                           <L 227>
    var_0 = &((var_scene).lights);
    var_2 = wp::load(var_0);
    var_1 = wp::address(var_2, var_li);
    var_4 = wp::load(var_1);
    var_3 = _pdf_link__locals__pdf_kind_6(var_scene, var_4, var_p, var_n, var_wi, var_t, var_tri);
    return var_3;
}


// /work/main/simulator/kernels/sampling.py:133
static void adj_sample_uniform_cone_0(
    wp::vec_t<2, wp::float32> var_u,
    wp::float32 var_one_minus_cos_max,
    wp::vec_t<2, wp::float32> & adj_u,
    wp::float32 & adj_one_minus_cos_max,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:148
static void adj_pdf_uniform_cone_0(
    wp::float32 var_one_minus_cos_max,
    wp::float32 & adj_one_minus_cos_max,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:99
static void adj_sample_concentric_disk_0(
    wp::vec_t<2, wp::float32> var_u,
    wp::vec_t<2, wp::float32> & adj_u,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/base.py:217
static void adj_empty_sample_0(
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/point.py:15
static void adj_sample_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:154
static void adj_one_minus_cos_from_sin2_0(
    wp::float32 var_sin2,
    wp::float32 & adj_sin2,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/sphere.py:18
static void adj_cone_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:73
static void adj_frame_x_0(
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:82
static void adj_frame_y_0(
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:91
static void adj_to_world_0(
    wp::vec_t<3, wp::float32> var_local,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_local,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/sphere.py:28
static void adj_sample_7(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/base.py:309
static void adj_behind_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    bool & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/rect.py:20
static void adj_corner_0(
    LightRec_73c30c8a var_l,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:197
static void adj_sphrect_setup_0(
    wp::vec_t<3, wp::float32> var_o,
    wp::vec_t<3, wp::float32> var_corner,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::float32 var_w,
    wp::float32 var_h,
    wp::vec_t<3, wp::float32> & adj_o,
    wp::vec_t<3, wp::float32> & adj_corner,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::float32 & adj_w,
    wp::float32 & adj_h,
    SphRect_7f5b29ec & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/base.py:261
static void adj_area_sample_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_q,
    wp::vec_t<3, wp::float32> var_nl,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_q,
    wp::vec_t<3, wp::float32> & adj_nl,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:240
static void adj_sphrect_sample_0(
    SphRect_7f5b29ec var_r,
    wp::vec_t<2, wp::float32> var_u,
    SphRect_7f5b29ec & adj_r,
    wp::vec_t<2, wp::float32> & adj_u,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/rect.py:25
static void adj_sample_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/disk.py:18
static void adj_sample_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/distant.py:19
static void adj_sample_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:78
static void adj_portal_guides_0(
    PortalRec_445c1fd2 var_pt,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    PortalRec_445c1fd2 & adj_pt,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    bool & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/closed_forms.py:79
static void adj__edge_term_0(
    wp::vec_t<3, wp::float64> var_a,
    wp::vec_t<3, wp::float64> var_b,
    wp::vec_t<3, wp::float64> var_n,
    wp::vec_t<3, wp::float64> & adj_a,
    wp::vec_t<3, wp::float64> & adj_b,
    wp::vec_t<3, wp::float64> & adj_n,
    wp::float64 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/closed_forms.py:91
static void adj_polygon_irradiance4_0(
    wp::vec_t<3, wp::float32> var_v0,
    wp::vec_t<3, wp::float32> var_v1,
    wp::vec_t<3, wp::float32> var_v2,
    wp::vec_t<3, wp::float32> var_v3,
    wp::int32 var_nv,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_v0,
    wp::vec_t<3, wp::float32> & adj_v1,
    wp::vec_t<3, wp::float32> & adj_v2,
    wp::vec_t<3, wp::float32> & adj_v3,
    wp::int32 & adj_nv,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:94
static void adj_portal_weight_0(
    PortalRec_445c1fd2 var_pt,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    bool var_single,
    PortalRec_445c1fd2 & adj_pt,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    bool & adj_single,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:111
static void adj_portals_total_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:121
static void adj_portal_density_0(
    PortalRec_445c1fd2 var_pt,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_wi,
    PortalRec_445c1fd2 & adj_pt,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:144
static void adj_pdf_portals_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_total,
    wp::int32 var_skip,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_total,
    wp::int32 & adj_skip,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/distributions.py:129
static void adj_latlong_texel_0(
    wp::vec_t<2, wp::float32> var_uv,
    wp::int32 var_w,
    wp::int32 var_h,
    wp::vec_t<2, wp::float32> & adj_uv,
    wp::int32 & adj_w,
    wp::int32 & adj_h,
    wp::int32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:67
static void adj_escaped_1(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_d,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_d,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:159
static void adj_sample_portals_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    wp::float32 var_total,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    wp::float32 & adj_total,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:50
static void adj_sample_map_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:117
static void adj_sample_cosine_hemisphere_0(
    wp::vec_t<2, wp::float32> var_u,
    wp::vec_t<2, wp::float32> & adj_u,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:125
static void adj_pdf_cosine_hemisphere_0(
    wp::float32 var_cos_theta,
    wp::float32 & adj_cos_theta,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:212
static void adj_sample_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/cylinder.py:27
static void adj_sample_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:34
static void adj_piece_estimate_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_k,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:59
static void adj_piece_weights_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_k,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:66
static void adj_piece_totals_0(
    SceneRec_19d73428 var_scene,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:75
static void adj_piece_probability_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<2, wp::float32> var_tot,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_k,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_tot,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:97
static void adj_pick_piece_0(
    SceneRec_19d73428 var_scene,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::float32 var_u,
    SceneRec_19d73428 & adj_scene,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::float32 & adj_u,
    PiecePick_dedfee88 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:131
static void adj_pick_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_k,
    wp::float32 var_u,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_k,
    wp::float32 & adj_u,
    wp::int32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/base.py:228
static void adj_tri_vertex_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_tri,
    wp::int32 var_k,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_tri,
    wp::int32 & adj_k,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/sampling.py:164
static void adj_sample_triangle_bary_0(
    wp::vec_t<2, wp::float32> var_u,
    wp::vec_t<2, wp::float32> & adj_u,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/base.py:252
static void adj_tri_emitted_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_tri,
    wp::float32 var_wo_dot_ng,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_tri,
    wp::float32 & adj_wo_dot_ng,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:146
static void adj_sample_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:110
static void adj__no_sample_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:101
static void adj__sample_link__locals__sample_kind_7(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:216
static void adj_sample_light_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_li,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_u,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_li,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_u,
    LightSample_1981fb4b & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/sphere.py:50
static void adj_pdf_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/base.py:284
static void adj_area_pdf_0(
    LightRec_73c30c8a var_l,
    wp::float32 var_cos_l,
    wp::float32 var_t,
    LightRec_73c30c8a & adj_l,
    wp::float32 & adj_cos_l,
    wp::float32 & adj_t,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/rect.py:49
static void adj_pdf_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/disk.py:26
static void adj_pdf_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/distant.py:37
static void adj_pdf_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
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
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:230
static void adj_pdf_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/cylinder.py:19
static void adj_side_normal_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_q,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_q,
    wp::vec_t<3, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/cylinder.py:37
static void adj_pdf_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/emissive.py:181
static void adj_pdf_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:125
static void adj__no_pdf_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:116
static void adj__pdf_link__locals__pdf_kind_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:222
static void adj_pdf_light_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_li,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_wi,
    wp::float32 var_t,
    wp::int32 var_tri,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_li,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_wi,
    wp::float32 & adj_t,
    wp::int32 & adj_tri,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}

struct wp_args_k_uniform_cone_05a72f36 {
    wp::int32 seed;
    wp::float32 omc;
    wp::array_t<wp::vec_t<3, wp::float32>> out;
    wp::array_t<wp::float32> pdf;
};


template <bool wp_linear_contiguous>
static void k_uniform_cone_05a72f36_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_uniform_cone_05a72f36 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_uniform_cone_05a72f36 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.out.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::int32 var_seed = _wp_args->seed;
    wp::float32 var_omc = _wp_args->omc;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out = _wp_args->out;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::float32 var_6;
    //---------
    // forward
    // def k_uniform_cone(seed: int, omc: float, out: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float)):       <L 83>
    // i = wp.tid()                                                                           <L 84>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 85>
    var_1 = wp::rand_init(var_seed, var_0);
    // out[i] = sample_uniform_cone(wp.vec2(wp.randf(rng), wp.randf(rng)), omc)               <L 86>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_uniform_cone_0(var_4, var_omc);
    wp::array_store(var_out, var_0, var_5);
    // pdf[i] = pdf_uniform_cone(omc)                                                         <L 87>
    var_6 = pdf_uniform_cone_0(var_omc);
    wp::array_store(var_pdf, var_0, var_6);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_uniform_cone_05a72f36_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_uniform_cone_05a72f36 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_uniform_cone_05a72f36_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_uniform_cone_05a72f36_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_uniform_cone_05a72f36 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->out.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_uniform_cone_05a72f36_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_uniform_cone_05a72f36_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_uniform_cone_05a72f36_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_uniform_cone_05a72f36 *_wp_args)
{
    k_uniform_cone_05a72f36_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_concentric_disk_33e214b0 {
    wp::int32 seed;
    wp::array_t<wp::vec_t<2, wp::float32>> out;
};


template <bool wp_linear_contiguous>
static void k_concentric_disk_33e214b0_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_concentric_disk_33e214b0 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_concentric_disk_33e214b0 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.out.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<2, wp::float32>> var_out = _wp_args->out;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def k_concentric_disk(seed: int, out: wp.array(dtype=wp.vec2)):                        <L 61>
    // i = wp.tid()                                                                           <L 62>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 63>
    var_1 = wp::rand_init(var_seed, var_0);
    // out[i] = sample_concentric_disk(wp.vec2(wp.randf(rng), wp.randf(rng)))                 <L 64>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_concentric_disk_0(var_4);
    wp::array_store(var_out, var_0, var_5);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_concentric_disk_33e214b0_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_concentric_disk_33e214b0 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_concentric_disk_33e214b0_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_concentric_disk_33e214b0_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_concentric_disk_33e214b0 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->out.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)));
    if (wp_linear_contiguous)
        k_concentric_disk_33e214b0_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_concentric_disk_33e214b0_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_concentric_disk_33e214b0_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_concentric_disk_33e214b0 *_wp_args)
{
    k_concentric_disk_33e214b0_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_sample_light_3f6a6fcf {
    SceneRec_19d73428 scene;
    wp::int32 li;
    wp::vec_t<3, wp::float32> p;
    wp::vec_t<3, wp::float32> n;
    wp::int32 seed;
    wp::array_t<wp::vec_t<3, wp::float32>> wi;
    wp::array_t<wp::float32> dist;
    wp::array_t<wp::float32> pdf;
    wp::array_t<wp::vec_t<2, wp::float32>> value;
    wp::array_t<wp::int32> tri;
    wp::array_t<wp::float32> pdf_again;
};


template <bool wp_linear_contiguous>
static void k_sample_light_3f6a6fcf_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_sample_light_3f6a6fcf *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_sample_light_3f6a6fcf wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.wi.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.dist.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.value.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        wp_contiguous_args.tri.strides[0] = sizeof(wp::int32);
        wp_contiguous_args.pdf_again.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    SceneRec_19d73428 var_scene = _wp_args->scene;
    wp::int32 var_li = _wp_args->li;
    wp::vec_t<3, wp::float32> var_p = _wp_args->p;
    wp::vec_t<3, wp::float32> var_n = _wp_args->n;
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> var_wi = _wp_args->wi;
    wp::array_t<wp::float32> var_dist = _wp_args->dist;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    wp::array_t<wp::vec_t<2, wp::float32>> var_value = _wp_args->value;
    wp::array_t<wp::int32> var_tri = _wp_args->tri;
    wp::array_t<wp::float32> var_pdf_again = _wp_args->pdf_again;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32> var_5;
    LightSample_1981fb4b var_6;
    wp::vec_t<3, wp::float32>* var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::float32* var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::float32* var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::vec_t<2, wp::float32>* var_16;
    wp::vec_t<2, wp::float32> var_17;
    wp::vec_t<2, wp::float32> var_18;
    wp::int32* var_19;
    wp::int32 var_20;
    wp::int32 var_21;
    wp::vec_t<3, wp::float32>* var_22;
    wp::float32* var_23;
    wp::int32* var_24;
    wp::float32 var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::float32 var_27;
    wp::int32 var_28;
    //---------
    // forward
    // def k_sample_light(                                                                    <L 117>
    // i = wp.tid()                                                                           <L 122>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 123>
    var_1 = wp::rand_init(var_seed, var_0);
    // s = sample_light(scene, li, p, n, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))       <L 124>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::randf(var_1);
    var_5 = wp::vec_t<3, wp::float32>(var_2, var_3, var_4);
    var_6 = sample_light_0(var_scene, var_li, var_p, var_n, var_5);
    // wi[i] = s.wi                                                                           <L 125>
    var_7 = &((var_6).wi);
    var_9 = wp::load(var_7);
    var_8 = wp::copy(var_9);
    wp::array_store(var_wi, var_0, var_8);
    // dist[i] = s.dist                                                                       <L 126>
    var_10 = &((var_6).dist);
    var_12 = wp::load(var_10);
    var_11 = wp::copy(var_12);
    wp::array_store(var_dist, var_0, var_11);
    // pdf[i] = s.pdf                                                                         <L 127>
    var_13 = &((var_6).pdf);
    var_15 = wp::load(var_13);
    var_14 = wp::copy(var_15);
    wp::array_store(var_pdf, var_0, var_14);
    // value[i] = s.value                                                                     <L 128>
    var_16 = &((var_6).value);
    var_18 = wp::load(var_16);
    var_17 = wp::copy(var_18);
    wp::array_store(var_value, var_0, var_17);
    // tri[i] = s.tri                                                                         <L 129>
    var_19 = &((var_6).tri);
    var_21 = wp::load(var_19);
    var_20 = wp::copy(var_21);
    wp::array_store(var_tri, var_0, var_20);
    // pdf_again[i] = pdf_light(scene, li, p, n, s.wi, s.dist, s.tri)                         <L 130>
    var_22 = &((var_6).wi);
    var_23 = &((var_6).dist);
    var_24 = &((var_6).tri);
    var_26 = wp::load(var_22);
    var_27 = wp::load(var_23);
    var_28 = wp::load(var_24);
    var_25 = pdf_light_0(var_scene, var_li, var_p, var_n, var_26, var_27, var_28);
    wp::array_store(var_pdf_again, var_0, var_25);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_sample_light_3f6a6fcf_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sample_light_3f6a6fcf *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_sample_light_3f6a6fcf_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_sample_light_3f6a6fcf_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sample_light_3f6a6fcf *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->wi.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->dist.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->value.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)) & (_wp_args->tri.strides[0] == (int)sizeof(wp::int32)) & (_wp_args->pdf_again.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_sample_light_3f6a6fcf_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_sample_light_3f6a6fcf_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_sample_light_3f6a6fcf_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sample_light_3f6a6fcf *_wp_args)
{
    k_sample_light_3f6a6fcf_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_cosine_hemisphere_76cf75e7 {
    wp::int32 seed;
    wp::array_t<wp::vec_t<3, wp::float32>> out;
    wp::array_t<wp::float32> pdf;
};


template <bool wp_linear_contiguous>
static void k_cosine_hemisphere_76cf75e7_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_cosine_hemisphere_76cf75e7 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_cosine_hemisphere_76cf75e7 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.out.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.pdf.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out = _wp_args->out;
    wp::array_t<wp::float32> var_pdf = _wp_args->pdf;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<3, wp::float32> var_5;
    const wp::int32 var_6 = 2;
    wp::float32 var_7;
    wp::float32 var_8;
    //---------
    // forward
    // def k_cosine_hemisphere(seed: int, out: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float)):       <L 68>
    // i = wp.tid()                                                                           <L 69>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 70>
    var_1 = wp::rand_init(var_seed, var_0);
    // d = sample_cosine_hemisphere(wp.vec2(wp.randf(rng), wp.randf(rng)))                    <L 71>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_cosine_hemisphere_0(var_4);
    // out[i] = d                                                                             <L 72>
    wp::array_store(var_out, var_0, var_5);
    // pdf[i] = pdf_cosine_hemisphere(d[2])                                                   <L 73>
    var_7 = wp::extract(var_5, var_6);
    var_8 = pdf_cosine_hemisphere_0(var_7);
    wp::array_store(var_pdf, var_0, var_8);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_cosine_hemisphere_76cf75e7_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_cosine_hemisphere_76cf75e7 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_cosine_hemisphere_76cf75e7_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_cosine_hemisphere_76cf75e7_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_cosine_hemisphere_76cf75e7 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->out.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->pdf.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_cosine_hemisphere_76cf75e7_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_cosine_hemisphere_76cf75e7_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_cosine_hemisphere_76cf75e7_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_cosine_hemisphere_76cf75e7 *_wp_args)
{
    k_cosine_hemisphere_76cf75e7_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_pdf_cosine_854610b5 {
    wp::array_t<wp::float32> cos_theta;
    wp::array_t<wp::float32> out;
};


template <bool wp_linear_contiguous>
static void k_pdf_cosine_854610b5_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_pdf_cosine_854610b5 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_pdf_cosine_854610b5 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.cos_theta.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.out.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::float32> var_cos_theta = _wp_args->cos_theta;
    wp::array_t<wp::float32> var_out = _wp_args->out;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::float32* var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    //---------
    // forward
    // def k_pdf_cosine(cos_theta: wp.array(dtype=float), out: wp.array(dtype=float)):        <L 77>
    // i = wp.tid()                                                                           <L 78>
    var_0 = builtin_tid1d();
    // out[i] = pdf_cosine_hemisphere(cos_theta[i])                                           <L 79>
    var_1 = wp::address(var_cos_theta, var_0);
    var_3 = wp::load(var_1);
    var_2 = pdf_cosine_hemisphere_0(var_3);
    wp::array_store(var_out, var_0, var_2);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_pdf_cosine_854610b5_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_pdf_cosine_854610b5 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_pdf_cosine_854610b5_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_pdf_cosine_854610b5_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_pdf_cosine_854610b5 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->cos_theta.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->out.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_pdf_cosine_854610b5_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_pdf_cosine_854610b5_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_pdf_cosine_854610b5_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_pdf_cosine_854610b5 *_wp_args)
{
    k_pdf_cosine_854610b5_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_frames_8909bc69 {
    wp::array_t<wp::vec_t<3, wp::float32>> n;
    wp::array_t<wp::vec_t<3, wp::float32>> x;
    wp::array_t<wp::vec_t<3, wp::float32>> y;
};


template <bool wp_linear_contiguous>
static void k_frames_8909bc69_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_frames_8909bc69 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_frames_8909bc69 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.n.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.x.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.y.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::array_t<wp::vec_t<3, wp::float32>> var_n = _wp_args->n;
    wp::array_t<wp::vec_t<3, wp::float32>> var_x = _wp_args->x;
    wp::array_t<wp::vec_t<3, wp::float32>> var_y = _wp_args->y;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<3, wp::float32>* var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::vec_t<3, wp::float32> var_6;
    //---------
    // forward
    // def k_frames(n: wp.array(dtype=wp.vec3), x: wp.array(dtype=wp.vec3), y: wp.array(dtype=wp.vec3)):       <L 110>
    // i = wp.tid()                                                                           <L 111>
    var_0 = builtin_tid1d();
    // x[i] = frame_x(n[i])                                                                   <L 112>
    var_1 = wp::address(var_n, var_0);
    var_3 = wp::load(var_1);
    var_2 = frame_x_0(var_3);
    wp::array_store(var_x, var_0, var_2);
    // y[i] = frame_y(n[i])                                                                   <L 113>
    var_4 = wp::address(var_n, var_0);
    var_6 = wp::load(var_4);
    var_5 = frame_y_0(var_6);
    wp::array_store(var_y, var_0, var_5);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_frames_8909bc69_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_frames_8909bc69 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_frames_8909bc69_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_frames_8909bc69_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_frames_8909bc69 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->n.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->x.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->y.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)));
    if (wp_linear_contiguous)
        k_frames_8909bc69_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_frames_8909bc69_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_frames_8909bc69_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_frames_8909bc69 *_wp_args)
{
    k_frames_8909bc69_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_sphrect_b51f06e1 {
    wp::int32 seed;
    wp::vec_t<3, wp::float32> o;
    wp::vec_t<3, wp::float32> corner;
    wp::vec_t<3, wp::float32> ex;
    wp::vec_t<3, wp::float32> ey;
    wp::float32 w;
    wp::float32 h;
    wp::array_t<wp::vec_t<3, wp::float32>> out;
    wp::array_t<wp::float32> solid_angle;
};


template <bool wp_linear_contiguous>
static void k_sphrect_b51f06e1_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_sphrect_b51f06e1 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_sphrect_b51f06e1 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.out.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.solid_angle.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::int32 var_seed = _wp_args->seed;
    wp::vec_t<3, wp::float32> var_o = _wp_args->o;
    wp::vec_t<3, wp::float32> var_corner = _wp_args->corner;
    wp::vec_t<3, wp::float32> var_ex = _wp_args->ex;
    wp::vec_t<3, wp::float32> var_ey = _wp_args->ey;
    wp::float32 var_w = _wp_args->w;
    wp::float32 var_h = _wp_args->h;
    wp::array_t<wp::vec_t<3, wp::float32>> var_out = _wp_args->out;
    wp::array_t<wp::float32> var_solid_angle = _wp_args->solid_angle;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    SphRect_7f5b29ec var_2;
    wp::float32 var_3;
    wp::float32 var_4;
    wp::vec_t<2, wp::float32> var_5;
    wp::vec_t<3, wp::float32> var_6;
    wp::float32* var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    //---------
    // forward
    // def k_sphrect(                                                                         <L 98>
    // i = wp.tid()                                                                           <L 102>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 103>
    var_1 = wp::rand_init(var_seed, var_0);
    // r = sphrect_setup(o, corner, ex, ey, w, h)                                             <L 104>
    var_2 = sphrect_setup_0(var_o, var_corner, var_ex, var_ey, var_w, var_h);
    // out[i] = sphrect_sample(r, wp.vec2(wp.randf(rng), wp.randf(rng)))                      <L 105>
    var_3 = wp::randf(var_1);
    var_4 = wp::randf(var_1);
    var_5 = wp::vec_t<2, wp::float32>(var_3, var_4);
    var_6 = sphrect_sample_0(var_2, var_5);
    wp::array_store(var_out, var_0, var_6);
    // solid_angle[i] = r.solid_angle                                                         <L 106>
    var_7 = &((var_2).solid_angle);
    var_9 = wp::load(var_7);
    var_8 = wp::copy(var_9);
    wp::array_store(var_solid_angle, var_0, var_8);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_sphrect_b51f06e1_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sphrect_b51f06e1 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_sphrect_b51f06e1_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_sphrect_b51f06e1_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sphrect_b51f06e1 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->out.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->solid_angle.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_sphrect_b51f06e1_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_sphrect_b51f06e1_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_sphrect_b51f06e1_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_sphrect_b51f06e1 *_wp_args)
{
    k_sphrect_b51f06e1_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_triangle_cd0313ea {
    wp::int32 seed;
    wp::array_t<wp::vec_t<2, wp::float32>> out;
};


template <bool wp_linear_contiguous>
static void k_triangle_cd0313ea_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_triangle_cd0313ea *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_triangle_cd0313ea wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.out.strides[0] = sizeof(wp::vec_t<2, wp::float32>);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    wp::int32 var_seed = _wp_args->seed;
    wp::array_t<wp::vec_t<2, wp::float32>> var_out = _wp_args->out;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::uint32 var_1;
    wp::float32 var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def k_triangle(seed: int, out: wp.array(dtype=wp.vec2)):                               <L 91>
    // i = wp.tid()                                                                           <L 92>
    var_0 = builtin_tid1d();
    // rng = wp.rand_init(seed, i)                                                            <L 93>
    var_1 = wp::rand_init(var_seed, var_0);
    // out[i] = sample_triangle_bary(wp.vec2(wp.randf(rng), wp.randf(rng)))                   <L 94>
    var_2 = wp::randf(var_1);
    var_3 = wp::randf(var_1);
    var_4 = wp::vec_t<2, wp::float32>(var_2, var_3);
    var_5 = sample_triangle_bary_0(var_4);
    wp::array_store(var_out, var_0, var_5);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_triangle_cd0313ea_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_triangle_cd0313ea *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_triangle_cd0313ea_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_triangle_cd0313ea_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_triangle_cd0313ea *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->out.strides[0] == (int)sizeof(wp::vec_t<2, wp::float32>)));
    if (wp_linear_contiguous)
        k_triangle_cd0313ea_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_triangle_cd0313ea_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_triangle_cd0313ea_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_triangle_cd0313ea *_wp_args)
{
    k_triangle_cd0313ea_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

struct wp_args_k_pdf_light_d239fc01 {
    SceneRec_19d73428 scene;
    wp::int32 li;
    wp::vec_t<3, wp::float32> p;
    wp::vec_t<3, wp::float32> n;
    wp::array_t<wp::vec_t<3, wp::float32>> wi;
    wp::array_t<wp::float32> t;
    wp::array_t<wp::int32> tri;
    wp::array_t<wp::float32> out;
};


template <bool wp_linear_contiguous>
static void k_pdf_light_d239fc01_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_k_pdf_light_d239fc01 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_k_pdf_light_d239fc01 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.wi.strides[0] = sizeof(wp::vec_t<3, wp::float32>);
        wp_contiguous_args.t.strides[0] = sizeof(wp::float32);
        wp_contiguous_args.tri.strides[0] = sizeof(wp::int32);
        wp_contiguous_args.out.strides[0] = sizeof(wp::float32);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    SceneRec_19d73428 var_scene = _wp_args->scene;
    wp::int32 var_li = _wp_args->li;
    wp::vec_t<3, wp::float32> var_p = _wp_args->p;
    wp::vec_t<3, wp::float32> var_n = _wp_args->n;
    wp::array_t<wp::vec_t<3, wp::float32>> var_wi = _wp_args->wi;
    wp::array_t<wp::float32> var_t = _wp_args->t;
    wp::array_t<wp::int32> var_tri = _wp_args->tri;
    wp::array_t<wp::float32> var_out = _wp_args->out;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::float32* var_2;
    wp::int32* var_3;
    wp::float32 var_4;
    wp::vec_t<3, wp::float32> var_5;
    wp::float32 var_6;
    wp::int32 var_7;
    //---------
    // forward
    // def k_pdf_light(                                                                       <L 134>
    // i = wp.tid()                                                                           <L 138>
    var_0 = builtin_tid1d();
    // out[i] = pdf_light(scene, li, p, n, wi[i], t[i], tri[i])                               <L 139>
    var_1 = wp::address(var_wi, var_0);
    var_2 = wp::address(var_t, var_0);
    var_3 = wp::address(var_tri, var_0);
    var_5 = wp::load(var_1);
    var_6 = wp::load(var_2);
    var_7 = wp::load(var_3);
    var_4 = pdf_light_0(var_scene, var_li, var_p, var_n, var_5, var_6, var_7);
    wp::array_store(var_out, var_0, var_4);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void k_pdf_light_d239fc01_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_pdf_light_d239fc01 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        k_pdf_light_d239fc01_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void k_pdf_light_d239fc01_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_pdf_light_d239fc01 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->wi.strides[0] == (int)sizeof(wp::vec_t<3, wp::float32>)) & (_wp_args->t.strides[0] == (int)sizeof(wp::float32)) & (_wp_args->tri.strides[0] == (int)sizeof(wp::int32)) & (_wp_args->out.strides[0] == (int)sizeof(wp::float32)));
    if (wp_linear_contiguous)
        k_pdf_light_d239fc01_cpu_forward_tasks<true>(dim, _wp_args);
    else
        k_pdf_light_d239fc01_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void k_pdf_light_d239fc01_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_k_pdf_light_d239fc01 *_wp_args)
{
    k_pdf_light_d239fc01_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

