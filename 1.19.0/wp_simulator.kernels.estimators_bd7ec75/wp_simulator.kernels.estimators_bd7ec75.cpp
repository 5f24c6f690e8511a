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




struct SensorRec_d6d15068
{
    wp::int32 kind;
    wp::vec_t<3, wp::float32> position;
    wp::vec_t<3, wp::float32> normal;
    wp::vec_t<3, wp::float32> right;
    wp::vec_t<3, wp::float32> up;
    wp::float32 width;
    wp::float32 height;
    wp::float32 one_minus_cos;
    wp::int32 cull;
    wp::int32 optics;


    SensorRec_d6d15068() = default;
    CUDA_CALLABLE SensorRec_d6d15068(wp::int32 const& kind,
    wp::vec_t<3, wp::float32> const& position = {},
    wp::vec_t<3, wp::float32> const& normal = {},
    wp::vec_t<3, wp::float32> const& right = {},
    wp::vec_t<3, wp::float32> const& up = {},
    wp::float32 const& width = {},
    wp::float32 const& height = {},
    wp::float32 const& one_minus_cos = {},
    wp::int32 const& cull = {},
    wp::int32 const& optics = {})
        : kind{kind}
        , position{position}
        , normal{normal}
        , right{right}
        , up{up}
        , width{width}
        , height{height}
        , one_minus_cos{one_minus_cos}
        , cull{cull}
        , optics{optics}

    {
    }

    CUDA_CALLABLE SensorRec_d6d15068& operator += (const SensorRec_d6d15068& rhs)
    {    kind += rhs.kind;
    position += rhs.position;
    normal += rhs.normal;
    right += rhs.right;
    up += rhs.up;
    width += rhs.width;
    height += rhs.height;
    one_minus_cos += rhs.one_minus_cos;
    cull += rhs.cull;
    optics += rhs.optics;

        return *this;}

};

static CUDA_CALLABLE void adj_SensorRec_d6d15068(wp::int32 const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::vec_t<3, wp::float32> const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::float32 const&,
    wp::int32 const&,
    wp::int32 const&,
    wp::int32 & adj_kind,
    wp::vec_t<3, wp::float32> & adj_position,
    wp::vec_t<3, wp::float32> & adj_normal,
    wp::vec_t<3, wp::float32> & adj_right,
    wp::vec_t<3, wp::float32> & adj_up,
    wp::float32 & adj_width,
    wp::float32 & adj_height,
    wp::float32 & adj_one_minus_cos,
    wp::int32 & adj_cull,
    wp::int32 & adj_optics,
    SensorRec_d6d15068 & adj_ret)
{
    adj_kind += adj_ret.kind;
    adj_position += adj_ret.position;
    adj_normal += adj_ret.normal;
    adj_right += adj_ret.right;
    adj_up += adj_ret.up;
    adj_width += adj_ret.width;
    adj_height += adj_ret.height;
    adj_one_minus_cos += adj_ret.one_minus_cos;
    adj_cull += adj_ret.cull;
    adj_optics += adj_ret.optics;
}

// Required when compiling adjoints.
CUDA_CALLABLE SensorRec_d6d15068 add(const SensorRec_d6d15068& a, const SensorRec_d6d15068& b)
{
    return SensorRec_d6d15068();
}

CUDA_CALLABLE void adj_atomic_add(SensorRec_d6d15068* p, SensorRec_d6d15068 t)
{
    wp::adj_atomic_add(&p->kind, t.kind);
    wp::adj_atomic_add(&p->position, t.position);
    wp::adj_atomic_add(&p->normal, t.normal);
    wp::adj_atomic_add(&p->right, t.right);
    wp::adj_atomic_add(&p->up, t.up);
    wp::adj_atomic_add(&p->width, t.width);
    wp::adj_atomic_add(&p->height, t.height);
    wp::adj_atomic_add(&p->one_minus_cos, t.one_minus_cos);
    wp::adj_atomic_add(&p->cull, t.cull);
    wp::adj_atomic_add(&p->optics, t.optics);
}




// /work/main/simulator/kernels/closed_forms.py:39
static wp::float32 point_irradiance_0(
    wp::vec_t<3, wp::float32> var_light_pos,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32> var_0;
    wp::float32 var_1;
    wp::float32 var_2;
    bool var_3;
    const wp::float32 var_4 = 0.0;
    bool var_5;
    const wp::float32 var_6 = 0.0;
    bool var_7;
    const wp::float32 var_8 = 0.0;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    //---------
    // forward
    // def point_irradiance(light_pos: wp.vec3, p: wp.vec3, n: wp.vec3) -> float:             <L 40>
    // d = light_pos - p                                                                      <L 42>
    var_0 = wp::sub(var_light_pos, var_p);
    // d2 = wp.length_sq(d)                                                                   <L 43>
    var_1 = wp::length_sq(var_0);
    // c = wp.dot(d, n)                                                                       <L 44>
    var_2 = wp::dot(var_0, var_n);
    // if c <= 0.0 or d2 <= 0.0:                                                              <L 45>
    var_5 = (var_2 <= var_4);
    var_3 = var_5;
    if (!var_3) {
        var_7 = (var_1 <= var_6);
        var_3 = var_3 || var_7;
    }
    if (var_3) {
        // return 0.0                                                                         <L 46>
        return var_8;
    }
    // return c / (d2 * wp.sqrt(d2))                                                          <L 47>
    var_9 = wp::sqrt(var_1);
    var_10 = wp::mul(var_1, var_9);
    var_11 = wp::div(var_2, var_10);
    return var_11;
}


// /work/main/simulator/kernels/lights/point.py:31
static wp::vec_t<2, wp::float32> analytic_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::vec_t<2, wp::float32>* var_0;
    wp::vec_t<3, wp::float32>* var_1;
    wp::float32 var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 32>
    // return l.emission * point_irradiance(l.position, p, n)                                 <L 33>
    var_0 = &((var_l).emission);
    var_1 = &((var_l).position);
    var_3 = wp::load(var_1);
    var_2 = point_irradiance_0(var_3, var_p, var_n);
    var_5 = wp::load(var_0);
    var_4 = wp::mul(var_5, var_2);
    return var_4;
}


// /work/main/simulator/kernels/closed_forms.py:50
static wp::float32 cap_irradiance_0(
    wp::vec_t<3, wp::float32> var_axis,
    wp::float32 var_sin2_sigma,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::float64 var_0;
    wp::float64 var_1;
    wp::float64 var_2;
    wp::vec_t<3, wp::float64> var_3;
    wp::vec_t<3, wp::float64> var_4;
    wp::float64 var_5;
    wp::float64 var_6;
    wp::float64 var_7;
    wp::float64 var_8;
    wp::float64 var_9;
    wp::float64 var_10;
    wp::float64 var_11;
    wp::float64 var_12;
    wp::float64 var_13;
    wp::float64 var_14;
    wp::float64 var_15;
    bool var_16;
    wp::float64 var_17;
    bool var_18;
    bool var_19;
    wp::float64 var_20;
    wp::float64 var_21;
    wp::float32 var_22;
    wp::float64 var_23;
    wp::float64 var_24;
    bool var_25;
    const wp::float32 var_26 = 0.0;
    bool var_27;
    wp::float64 var_28;
    wp::float64 var_29;
    wp::float32 var_30;
    wp::float64 var_31;
    wp::float64 var_32;
    wp::float64 var_33;
    wp::float64 var_34;
    wp::float64 var_35;
    wp::float64 var_36;
    wp::float64 var_37;
    wp::float64 var_38;
    wp::float64 var_39;
    wp::float64 var_40;
    wp::float64 var_41;
    wp::float64 var_42;
    wp::float64 var_43;
    wp::float64 var_44;
    wp::float64 var_45;
    wp::float64 var_46;
    wp::float64 var_47;
    wp::float64 var_48;
    wp::float64 var_49;
    wp::float64 var_50;
    wp::float64 var_51;
    wp::float32 var_52;
    //---------
    // forward
    // def cap_irradiance(axis: wp.vec3, sin2_sigma: float, n: wp.vec3) -> float:             <L 51>
    // f0 = wp.float64(0.0)                                                                   <L 58>
    var_0 = 0.0;
    // f1 = wp.float64(1.0)                                                                   <L 59>
    var_1 = 1.0;
    // s2 = wp.float64(sin2_sigma)                                                            <L 60>
    var_2 = wp::float64(var_sin2_sigma);
    // cos_t = wp.clamp(wp.dot(wp.vec3d(axis), wp.vec3d(n)), -f1, f1)                         <L 61>
    var_3 = wp::vec_t<3, wp::float64>(var_axis);
    var_4 = wp::vec_t<3, wp::float64>(var_n);
    var_5 = wp::dot(var_3, var_4);
    var_6 = wp::neg(var_1);
    var_7 = wp::clamp(var_5, var_6, var_1);
    // sin_t = wp.sqrt(wp.max(f0, f1 - cos_t * cos_t))                                        <L 62>
    var_8 = wp::mul(var_7, var_7);
    var_9 = wp::sub(var_1, var_8);
    var_10 = wp::max(var_0, var_9);
    var_11 = wp::sqrt(var_10);
    // cos_s = wp.sqrt(wp.max(f0, f1 - s2))                                                   <L 63>
    var_12 = wp::sub(var_1, var_2);
    var_13 = wp::max(var_0, var_12);
    var_14 = wp::sqrt(var_13);
    // pi = wp.float64(PI)                                                                    <L 64>
    var_15 = 3.141592653589793;
    // if cos_t * cos_t > s2 and cos_t > f0:                                                  <L 66>
    var_17 = wp::mul(var_7, var_7);
    var_18 = (var_17 > var_2);
    var_16 = var_18;
    if (var_16) {
        var_19 = (var_7 > var_0);
        var_16 = var_16 && var_19;
    }
    if (var_16) {
        // return float(pi * s2 * cos_t)                                                      <L 67>
        var_20 = wp::mul(var_15, var_2);
        var_21 = wp::mul(var_20, var_7);
        var_22 = wp::float(var_21);
        return var_22;
    }
    // if cos_t <= -wp.sqrt(s2):                                                              <L 69>
    var_23 = wp::sqrt(var_2);
    var_24 = wp::neg(var_23);
    var_25 = (var_7 <= var_24);
    if (var_25) {
        // return 0.0                                                                         <L 70>
        return var_26;
    }
    // if sin_t <= f0:                                                                        <L 71>
    var_27 = (var_11 <= var_0);
    if (var_27) {
        // return float(pi * s2 * cos_t)                                                      <L 72>
        var_28 = wp::mul(var_15, var_2);
        var_29 = wp::mul(var_28, var_7);
        var_30 = wp::float(var_29);
        return var_30;
    }
    // x = cos_s / wp.sqrt(s2)  # √(1/sin²σ − 1)                                              <L 73>
    var_31 = wp::sqrt(var_2);
    var_32 = wp::div(var_14, var_31);
    // y = wp.clamp(-x * cos_t / sin_t, -f1, f1)                                              <L 74>
    var_33 = wp::neg(var_32);
    var_34 = wp::mul(var_33, var_7);
    var_35 = wp::div(var_34, var_11);
    var_36 = wp::neg(var_1);
    var_37 = wp::clamp(var_35, var_36, var_1);
    // sy = wp.sqrt(wp.max(f0, f1 - y * y))                                                   <L 75>
    var_38 = wp::mul(var_37, var_37);
    var_39 = wp::sub(var_1, var_38);
    var_40 = wp::max(var_0, var_39);
    var_41 = wp::sqrt(var_40);
    // return float((cos_t * wp.acos(y) - x * sin_t * sy) * s2 + wp.atan(sin_t * sy / x))       <L 76>
    var_42 = wp::acos(var_37);
    var_43 = wp::mul(var_7, var_42);
    var_44 = wp::mul(var_32, var_11);
    var_45 = wp::mul(var_44, var_41);
    var_46 = wp::sub(var_43, var_45);
    var_47 = wp::mul(var_46, var_2);
    var_48 = wp::mul(var_11, var_41);
    var_49 = wp::div(var_48, var_32);
    var_50 = wp::atan(var_49);
    var_51 = wp::add(var_47, var_50);
    var_52 = wp::float(var_51);
    return var_52;
}


// /work/main/simulator/kernels/lights/sphere.py:77
static wp::vec_t<2, wp::float32> analytic_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
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
    const wp::float32 var_11 = 0.0;
    wp::vec_t<2, wp::float32> var_12;
    wp::vec_t<2, wp::float32>* var_13;
    wp::float32 var_14;
    wp::vec_t<3, wp::float32> var_15;
    wp::float32* var_16;
    wp::float32* var_17;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::vec_t<2, wp::float32> var_23;
    wp::vec_t<2, wp::float32> var_24;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 78>
    // d = l.position - p                                                                     <L 79>
    var_0 = &((var_l).position);
    var_2 = wp::load(var_0);
    var_1 = wp::sub(var_2, var_p);
    // d2 = wp.length_sq(d)                                                                   <L 80>
    var_3 = wp::length_sq(var_1);
    // if d2 <= l.radius * l.radius:                                                          <L 81>
    var_4 = &((var_l).radius);
    var_5 = &((var_l).radius);
    var_7 = wp::load(var_4);
    var_8 = wp::load(var_5);
    var_6 = wp::mul(var_7, var_8);
    var_9 = (var_3 <= var_6);
    if (var_9) {
        // return wp.vec2(0.0, 0.0)                                                           <L 82>
        var_12 = wp::vec_t<2, wp::float32>(var_10, var_11);
        return var_12;
    }
    // return l.emission * cap_irradiance(d / wp.sqrt(d2), l.radius * l.radius / d2, n)       <L 83>
    var_13 = &((var_l).emission);
    var_14 = wp::sqrt(var_3);
    var_15 = wp::div(var_1, var_14);
    var_16 = &((var_l).radius);
    var_17 = &((var_l).radius);
    var_19 = wp::load(var_16);
    var_20 = wp::load(var_17);
    var_18 = wp::mul(var_19, var_20);
    var_21 = wp::div(var_18, var_3);
    var_22 = cap_irradiance_0(var_15, var_21, var_n);
    var_24 = wp::load(var_13);
    var_23 = wp::mul(var_24, var_22);
    return var_23;
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


// /work/main/simulator/kernels/lights/rect.py:63
static wp::vec_t<2, wp::float32> analytic_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    bool var_0;
    const wp::float32 var_1 = 0.0;
    const wp::float32 var_2 = 0.0;
    wp::vec_t<2, wp::float32> var_3;
    const wp::float32 var_4 = 0.5;
    wp::float32* var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::vec_t<3, wp::float32>* var_8;
    wp::vec_t<3, wp::float32> var_9;
    wp::vec_t<3, wp::float32> var_10;
    const wp::float32 var_11 = 0.5;
    wp::float32* var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::vec_t<3, wp::float32>* var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::vec_t<3, wp::float32>* var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<2, wp::float32>* var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32> var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::vec_t<3, wp::float32> var_27;
    wp::vec_t<3, wp::float32> var_28;
    wp::vec_t<3, wp::float32> var_29;
    const wp::int32 var_30 = 4;
    wp::float32 var_31;
    wp::vec_t<2, wp::float32> var_32;
    wp::vec_t<2, wp::float32> var_33;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 64>
    // if behind(l, p):                                                                       <L 65>
    var_0 = behind_0(var_l, var_p);
    if (var_0) {
        // return wp.vec2(0.0, 0.0)  # behind a one-sided emitter                             <L 66>
        var_3 = wp::vec_t<2, wp::float32>(var_1, var_2);
        return var_3;
    }
    // hx = 0.5 * l.width * l.ex                                                              <L 67>
    var_5 = &((var_l).width);
    var_7 = wp::load(var_5);
    var_6 = wp::mul(var_4, var_7);
    var_8 = &((var_l).ex);
    var_10 = wp::load(var_8);
    var_9 = wp::mul(var_6, var_10);
    // hy = 0.5 * l.height * l.ey                                                             <L 68>
    var_12 = &((var_l).height);
    var_14 = wp::load(var_12);
    var_13 = wp::mul(var_11, var_14);
    var_15 = &((var_l).ey);
    var_17 = wp::load(var_15);
    var_16 = wp::mul(var_13, var_17);
    // c = l.position                                                                         <L 69>
    var_18 = &((var_l).position);
    var_20 = wp::load(var_18);
    var_19 = wp::copy(var_20);
    // return l.emission * polygon_irradiance4(c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy, 4, p, n)       <L 70>
    var_21 = &((var_l).emission);
    var_22 = wp::sub(var_19, var_9);
    var_23 = wp::sub(var_22, var_16);
    var_24 = wp::add(var_19, var_9);
    var_25 = wp::sub(var_24, var_16);
    var_26 = wp::add(var_19, var_9);
    var_27 = wp::add(var_26, var_16);
    var_28 = wp::sub(var_19, var_9);
    var_29 = wp::add(var_28, var_16);
    var_31 = polygon_irradiance4_0(var_23, var_25, var_27, var_29, var_30, var_p, var_n);
    var_33 = wp::load(var_21);
    var_32 = wp::mul(var_33, var_31);
    return var_32;
}


// /work/main/simulator/kernels/closed_forms.py:152
static wp::float32 disk_irradiance_0(
    wp::vec_t<3, wp::float32> var_centre,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::float32 var_radius,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::float64 var_0;
    const wp::int32 var_1 = 256;
    wp::int32 var_2;
    wp::float64 var_3;
    wp::float32 var_4;
    wp::float64 var_5;
    wp::float64 var_6;
    wp::vec_t<3, wp::float64> var_7;
    wp::vec_t<3, wp::float64> var_8;
    wp::vec_t<3, wp::float64> var_9;
    wp::vec_t<3, wp::float64> var_10;
    wp::vec_t<3, wp::float64> var_11;
    wp::vec_t<3, wp::float64> var_12;
    wp::float64 var_13;
    wp::range_t var_14;
    wp::int32 var_15;
    wp::float32 var_16;
    wp::float64 var_17;
    wp::float64 var_18;
    wp::float64 var_19;
    wp::float64 var_20;
    wp::vec_t<3, wp::float64> var_21;
    wp::vec_t<3, wp::float64> var_22;
    wp::vec_t<3, wp::float64> var_23;
    wp::vec_t<3, wp::float64> var_24;
    wp::vec_t<3, wp::float64> var_25;
    wp::float64 var_26;
    wp::vec_t<3, wp::float64> var_27;
    wp::vec_t<3, wp::float64> var_28;
    wp::vec_t<3, wp::float64> var_29;
    wp::vec_t<3, wp::float64> var_30;
    wp::vec_t<3, wp::float64> var_31;
    wp::float64 var_32;
    wp::float64 var_33;
    wp::float64 var_34;
    wp::float64 var_35;
    wp::float64 var_36;
    wp::float64 var_37;
    wp::float64 var_38;
    wp::float64 var_39;
    wp::float32 var_40;
    //---------
    // forward
    // def disk_irradiance(centre: wp.vec3, ex: wp.vec3, ey: wp.vec3, radius: float, p: wp.vec3, n: wp.vec3) -> float:       <L 153>
    // acc = wp.float64(0.0)                                                                  <L 158>
    var_0 = 0.0;
    // nodes = int(DISK_NODES)                                                                <L 159>
    var_2 = wp::int(var_1);
    // h = wp.float64(TWO_PI) / wp.float64(float(nodes))                                      <L 160>
    var_3 = 6.283185307179586;
    var_4 = wp::float(var_2);
    var_5 = wp::float64(var_4);
    var_6 = wp::div(var_3, var_5);
    // c0 = wp.vec3d(centre) - wp.vec3d(p)                                                    <L 161>
    var_7 = wp::vec_t<3, wp::float64>(var_centre);
    var_8 = wp::vec_t<3, wp::float64>(var_p);
    var_9 = wp::sub(var_7, var_8);
    // exd = wp.vec3d(ex)                                                                     <L 162>
    var_10 = wp::vec_t<3, wp::float64>(var_ex);
    // eyd = wp.vec3d(ey)                                                                     <L 163>
    var_11 = wp::vec_t<3, wp::float64>(var_ey);
    // nd = wp.vec3d(n)                                                                       <L 164>
    var_12 = wp::vec_t<3, wp::float64>(var_n);
    // rad = wp.float64(radius)                                                               <L 165>
    var_13 = wp::float64(var_radius);
    // for k in range(nodes):                                                                 <L 166>
    var_14 = wp::range(var_2);
    start_for_0:;
        if (iter_cmp(var_14) == 0) goto end_for_0;
        var_15 = wp::iter_next(var_14);
        // phi = wp.float64(float(k)) * h                                                     <L 167>
        var_16 = wp::float(var_15);
        var_17 = wp::float64(var_16);
        var_18 = wp::mul(var_17, var_6);
        // c = wp.cos(phi)                                                                    <L 168>
        var_19 = wp::cos(var_18);
        // s = wp.sin(phi)                                                                    <L 169>
        var_20 = wp::sin(var_18);
        // r = c0 + rad * (c * exd + s * eyd)                                                 <L 170>
        var_21 = wp::mul(var_19, var_10);
        var_22 = wp::mul(var_20, var_11);
        var_23 = wp::add(var_21, var_22);
        var_24 = wp::mul(var_13, var_23);
        var_25 = wp::add(var_9, var_24);
        // dr = rad * (-s * exd + c * eyd)                                                    <L 171>
        var_26 = wp::neg(var_20);
        var_27 = wp::mul(var_26, var_10);
        var_28 = wp::mul(var_19, var_11);
        var_29 = wp::add(var_27, var_28);
        var_30 = wp::mul(var_13, var_29);
        // acc += wp.dot(nd, wp.cross(r, dr)) / wp.length_sq(r)                               <L 172>
        var_31 = wp::cross(var_25, var_30);
        var_32 = wp::dot(var_12, var_31);
        var_33 = wp::length_sq(var_25);
        var_34 = wp::div(var_32, var_33);
        var_35 = wp::add(var_0, var_34);
        wp::assign(var_0, var_35);
        goto start_for_0;
    end_for_0:;
    // return float(wp.float64(0.5) * wp.abs(acc * h))                                        <L 173>
    var_36 = 0.5;
    var_37 = wp::mul(var_0, var_6);
    var_38 = wp::abs(var_37);
    var_39 = wp::mul(var_36, var_38);
    var_40 = wp::float(var_39);
    return var_40;
}


// /work/main/simulator/kernels/lights/disk.py:37
static wp::vec_t<2, wp::float32> analytic_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    bool var_0;
    const wp::float32 var_1 = 0.0;
    const wp::float32 var_2 = 0.0;
    wp::vec_t<2, wp::float32> var_3;
    wp::vec_t<2, wp::float32>* var_4;
    wp::vec_t<3, wp::float32>* var_5;
    wp::vec_t<3, wp::float32>* var_6;
    wp::vec_t<3, wp::float32>* var_7;
    wp::float32* var_8;
    wp::float32 var_9;
    wp::vec_t<3, wp::float32> var_10;
    wp::vec_t<3, wp::float32> var_11;
    wp::vec_t<3, wp::float32> var_12;
    wp::float32 var_13;
    wp::vec_t<2, wp::float32> var_14;
    wp::vec_t<2, wp::float32> var_15;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 38>
    // if behind(l, p):                                                                       <L 39>
    var_0 = behind_0(var_l, var_p);
    if (var_0) {
        // return wp.vec2(0.0, 0.0)  # behind a one-sided emitter                             <L 40>
        var_3 = wp::vec_t<2, wp::float32>(var_1, var_2);
        return var_3;
    }
    // return l.emission * disk_irradiance(l.position, l.ex, l.ey, l.radius, p, n)            <L 41>
    var_4 = &((var_l).emission);
    var_5 = &((var_l).position);
    var_6 = &((var_l).ex);
    var_7 = &((var_l).ey);
    var_8 = &((var_l).radius);
    var_10 = wp::load(var_5);
    var_11 = wp::load(var_6);
    var_12 = wp::load(var_7);
    var_13 = wp::load(var_8);
    var_9 = disk_irradiance_0(var_10, var_11, var_12, var_13, var_p, var_n);
    var_15 = wp::load(var_4);
    var_14 = wp::mul(var_15, var_9);
    return var_14;
}


// /work/main/simulator/kernels/lights/distant.py:50
static wp::vec_t<2, wp::float32> analytic_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::float32* var_0;
    const wp::float32 var_1 = 0.0;
    bool var_2;
    wp::float32 var_3;
    wp::vec_t<2, wp::float32>* var_4;
    const wp::float32 var_5 = 0.0;
    wp::vec_t<3, wp::float32>* var_6;
    wp::float32 var_7;
    wp::vec_t<3, wp::float32> var_8;
    wp::float32 var_9;
    wp::vec_t<2, wp::float32> var_10;
    wp::vec_t<2, wp::float32> var_11;
    wp::float32* var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::vec_t<2, wp::float32>* var_15;
    wp::vec_t<3, wp::float32>* var_16;
    const wp::float32 var_17 = 2.0;
    wp::float32 var_18;
    wp::float32 var_19;
    wp::float32 var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::vec_t<2, wp::float32> var_22;
    wp::vec_t<2, wp::float32> var_23;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 51>
    // if l.one_minus_cos <= 0.0:                                                             <L 52>
    var_0 = &((var_l).one_minus_cos);
    var_3 = wp::load(var_0);
    var_2 = (var_3 <= var_1);
    if (var_2) {
        // return l.emission * wp.max(0.0, wp.dot(l.ez, n))                                   <L 53>
        var_4 = &((var_l).emission);
        var_6 = &((var_l).ez);
        var_8 = wp::load(var_6);
        var_7 = wp::dot(var_8, var_n);
        var_9 = wp::max(var_5, var_7);
        var_11 = wp::load(var_4);
        var_10 = wp::mul(var_11, var_9);
        return var_10;
    }
    // omc = l.one_minus_cos                                                                  <L 54>
    var_12 = &((var_l).one_minus_cos);
    var_14 = wp::load(var_12);
    var_13 = wp::copy(var_14);
    // return l.emission * cap_irradiance(l.ez, omc * (2.0 - omc), n)                         <L 55>
    var_15 = &((var_l).emission);
    var_16 = &((var_l).ez);
    var_18 = wp::sub(var_17, var_13);
    var_19 = wp::mul(var_13, var_18);
    var_21 = wp::load(var_16);
    var_20 = cap_irradiance_0(var_21, var_19, var_n);
    var_23 = wp::load(var_15);
    var_22 = wp::mul(var_23, var_20);
    return var_22;
}


// /work/main/simulator/kernels/lights/dome.py:241
static wp::vec_t<2, wp::float32> analytic_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::vec_t<2, wp::float32>* var_0;
    const wp::float32 var_1 = 3.141592653589793;
    wp::vec_t<2, wp::float32> var_2;
    wp::vec_t<2, wp::float32> var_3;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 242>
    // return l.emission * PI  # the whole upper hemisphere is sky                            <L 243>
    var_0 = &((var_l).emission);
    var_3 = wp::load(var_0);
    var_2 = wp::mul(var_3, var_1);
    return var_2;
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


// /work/main/simulator/kernels/lights/emissive.py:198
static wp::vec_t<2, wp::float32> analytic_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    const wp::float32 var_1 = 0.0;
    wp::vec_t<2, wp::float32> var_2;
    wp::array_t<wp::int32>* var_3;
    wp::shape_t* var_4;
    const wp::int32 var_5 = 0;
    wp::int32 var_6;
    wp::shape_t var_7;
    wp::range_t var_8;
    wp::int32 var_9;
    wp::array_t<wp::int32>* var_10;
    wp::int32* var_11;
    wp::array_t<wp::int32> var_12;
    wp::int32 var_13;
    wp::int32 var_14;
    const wp::int32 var_15 = 0;
    wp::vec_t<3, wp::float32> var_16;
    const wp::int32 var_17 = 1;
    wp::vec_t<3, wp::float32> var_18;
    const wp::int32 var_19 = 2;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32> var_24;
    wp::float32 var_25;
    wp::vec_t<2, wp::float32> var_26;
    bool var_27;
    const wp::int32 var_28 = 0;
    wp::float32 var_29;
    const wp::float32 var_30 = 0.0;
    bool var_31;
    const wp::int32 var_32 = 1;
    wp::float32 var_33;
    const wp::float32 var_34 = 0.0;
    bool var_35;
    const wp::int32 var_36 = 3;
    wp::float32 var_37;
    wp::vec_t<2, wp::float32> var_38;
    wp::vec_t<2, wp::float32> var_39;
    wp::vec_t<2, wp::float32> var_40;
    //---------
    // forward
    // def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:         <L 199>
    // total = wp.vec2(0.0, 0.0)                                                              <L 200>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    // for k in range(scene.emit_tris.shape[0]):                                              <L 201>
    var_3 = &((var_scene).emit_tris);
    var_4 = &(var_3->shape);
    var_7 = wp::load(var_4);
    var_6 = wp::extract(var_7, var_5);
    var_8 = wp::range(var_6);
    start_for_0:;
        if (iter_cmp(var_8) == 0) goto end_for_0;
        var_9 = wp::iter_next(var_8);
        // tri = scene.emit_tris[k]                                                           <L 202>
        var_10 = &((var_scene).emit_tris);
        var_12 = wp::load(var_10);
        var_11 = wp::address(var_12, var_9);
        var_14 = wp::load(var_11);
        var_13 = wp::copy(var_14);
        // a = tri_vertex(scene, tri, 0)                                                      <L 203>
        var_16 = tri_vertex_0(var_scene, var_13, var_15);
        // b = tri_vertex(scene, tri, 1)                                                      <L 204>
        var_18 = tri_vertex_0(var_scene, var_13, var_17);
        // c = tri_vertex(scene, tri, 2)                                                      <L 205>
        var_20 = tri_vertex_0(var_scene, var_13, var_19);
        // facing = wp.dot(p - a, wp.cross(b - a, c - a))  # > 0: p in front                  <L 206>
        var_21 = wp::sub(var_p, var_16);
        var_22 = wp::sub(var_18, var_16);
        var_23 = wp::sub(var_20, var_16);
        var_24 = wp::cross(var_22, var_23);
        var_25 = wp::dot(var_21, var_24);
        // le = tri_emitted(scene, tri, facing)                                               <L 207>
        var_26 = tri_emitted_0(var_scene, var_13, var_25);
        // if le[0] > 0.0 or le[1] > 0.0:                                                     <L 208>
        var_29 = wp::extract(var_26, var_28);
        var_31 = (var_29 > var_30);
        var_27 = var_31;
        if (!var_27) {
            var_33 = wp::extract(var_26, var_32);
            var_35 = (var_33 > var_34);
            var_27 = var_27 || var_35;
        }
        if (var_27) {
            // total += le * polygon_irradiance4(a, b, c, c, 3, p, n)                         <L 209>
            var_37 = polygon_irradiance4_0(var_16, var_18, var_20, var_20, var_36, var_p, var_n);
            var_38 = wp::mul(var_26, var_37);
            var_39 = wp::add(var_2, var_38);
        }
        var_40 = wp::where(var_27, var_39, var_2);
        wp::assign(var_2, var_40);
        goto start_for_0;
    end_for_0:;
    // return total                                                                           <L 210>
    return var_2;
}


// /work/main/simulator/kernels/lights/__init__.py:185
static wp::vec_t<2, wp::float32> _no_analytic_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    const wp::float32 var_1 = 0.0;
    wp::vec_t<2, wp::float32> var_2;
    //---------
    // forward
    // def _no_analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 186>
    // return wp.vec2(0.0, 0.0)                                                               <L 187>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    return var_2;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 7;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_3(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _no_analytic_0(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 5;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_2(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _analytic_link__locals__analytic_kind_0(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 4;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_1(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _analytic_link__locals__analytic_kind_1(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 3;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_0(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _analytic_link__locals__analytic_kind_2(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 2;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_5(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _analytic_link__locals__analytic_kind_3(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 1;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_6(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _analytic_link__locals__analytic_kind_4(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:176
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 177>
    // if l.kind == wp.static(k):                                                             <L 178>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, l, p, n)                                             <L 179>
        var_4 = analytic_4(var_scene, var_l, var_p, var_n);
        return var_4;
    }
    // return wp.static(rest)(scene, l, p, n)                                                 <L 180>
    var_5 = _analytic_link__locals__analytic_kind_5(var_scene, var_l, var_p, var_n);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:252
static wp::vec_t<2, wp::float32> analytic_light_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_li,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n)
{
    //---------
    // primal vars
    wp::array_t<LightRec_73c30c8a>* var_0;
    LightRec_73c30c8a* var_1;
    wp::array_t<LightRec_73c30c8a> var_2;
    wp::vec_t<2, wp::float32> var_3;
    LightRec_73c30c8a var_4;
    //---------
    // forward
    // def analytic_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:       <L 253>
    // return _analytic_chain(scene, scene.lights[li], p, n)                                  <L 256>
    var_0 = &((var_scene).lights);
    var_2 = wp::load(var_0);
    var_1 = wp::address(var_2, var_li);
    var_4 = wp::load(var_1);
    var_3 = _analytic_link__locals__analytic_kind_6(var_scene, var_4, var_p, var_n);
    return var_3;
}


// /work/main/simulator/kernels/shaping.py:14
static wp::float32 ies_candela_0(
    LightRec_73c30c8a var_l,
    wp::float32 var_theta_deg,
    wp::float32 var_phi_deg)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    const wp::float32 var_1 = 180.0;
    wp::float32 var_2;
    const wp::float32 var_3 = 180.0;
    wp::float32 var_4;
    wp::int32* var_5;
    const wp::int32 var_6 = 1;
    wp::int32 var_7;
    wp::int32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    const wp::float32 var_11 = 0.0;
    const wp::float32 var_12 = 360.0;
    wp::float32 var_13;
    const wp::float32 var_14 = 360.0;
    wp::float32 var_15;
    wp::int32* var_16;
    const wp::int32 var_17 = 1;
    wp::int32 var_18;
    wp::int32 var_19;
    wp::float32 var_20;
    wp::float32 var_21;
    wp::float32 var_22;
    wp::int32 var_23;
    const wp::int32 var_24 = 0;
    wp::int32* var_25;
    const wp::int32 var_26 = 2;
    wp::int32 var_27;
    wp::int32 var_28;
    wp::int32 var_29;
    wp::float32 var_30;
    wp::int32 var_31;
    const wp::int32 var_32 = 0;
    wp::int32* var_33;
    const wp::int32 var_34 = 2;
    wp::int32 var_35;
    wp::int32 var_36;
    wp::int32 var_37;
    wp::float32 var_38;
    wp::float32 var_39;
    const wp::float32 var_40 = 0.0;
    const wp::float32 var_41 = 1.0;
    wp::float32 var_42;
    wp::float32 var_43;
    wp::float32 var_44;
    const wp::float32 var_45 = 0.0;
    const wp::float32 var_46 = 1.0;
    wp::float32 var_47;
    wp::int32* var_48;
    wp::int32 var_49;
    wp::int32 var_50;
    const wp::float32 var_51 = 1.0;
    wp::float32 var_52;
    wp::array_t<wp::float32>* var_53;
    wp::int32 var_54;
    wp::int32 var_55;
    wp::float32* var_56;
    wp::array_t<wp::float32> var_57;
    wp::float32 var_58;
    wp::float32 var_59;
    wp::array_t<wp::float32>* var_60;
    wp::int32 var_61;
    wp::int32 var_62;
    const wp::int32 var_63 = 1;
    wp::int32 var_64;
    wp::float32* var_65;
    wp::array_t<wp::float32> var_66;
    wp::float32 var_67;
    wp::float32 var_68;
    wp::float32 var_69;
    const wp::float32 var_70 = 1.0;
    wp::float32 var_71;
    wp::array_t<wp::float32>* var_72;
    const wp::int32 var_73 = 1;
    wp::int32 var_74;
    wp::int32 var_75;
    wp::int32 var_76;
    wp::float32* var_77;
    wp::array_t<wp::float32> var_78;
    wp::float32 var_79;
    wp::float32 var_80;
    wp::array_t<wp::float32>* var_81;
    const wp::int32 var_82 = 1;
    wp::int32 var_83;
    wp::int32 var_84;
    wp::int32 var_85;
    const wp::int32 var_86 = 1;
    wp::int32 var_87;
    wp::float32* var_88;
    wp::array_t<wp::float32> var_89;
    wp::float32 var_90;
    wp::float32 var_91;
    wp::float32 var_92;
    const wp::float32 var_93 = 1.0;
    wp::float32 var_94;
    wp::float32 var_95;
    wp::float32 var_96;
    wp::float32 var_97;
    //---------
    // forward
    // def ies_candela(l: LightRec, theta_deg: float, phi_deg: float) -> float:               <L 15>
    // ft = wp.clamp(theta_deg, 0.0, 180.0) / 180.0 * float(l.map_h - 1)                      <L 20>
    var_2 = wp::clamp(var_theta_deg, var_0, var_1);
    var_4 = wp::div(var_2, var_3);
    var_5 = &((var_l).map_h);
    var_8 = wp::load(var_5);
    var_7 = wp::sub(var_8, var_6);
    var_9 = wp::float(var_7);
    var_10 = wp::mul(var_4, var_9);
    // fp = wp.clamp(phi_deg, 0.0, 360.0) / 360.0 * float(l.map_w - 1)                        <L 21>
    var_13 = wp::clamp(var_phi_deg, var_11, var_12);
    var_15 = wp::div(var_13, var_14);
    var_16 = &((var_l).map_w);
    var_19 = wp::load(var_16);
    var_18 = wp::sub(var_19, var_17);
    var_20 = wp::float(var_18);
    var_21 = wp::mul(var_15, var_20);
    // i = wp.clamp(int(wp.floor(ft)), 0, l.map_h - 2)                                        <L 22>
    var_22 = wp::floor(var_10);
    var_23 = wp::int(var_22);
    var_25 = &((var_l).map_h);
    var_28 = wp::load(var_25);
    var_27 = wp::sub(var_28, var_26);
    var_29 = wp::clamp(var_23, var_24, var_27);
    // j = wp.clamp(int(wp.floor(fp)), 0, l.map_w - 2)                                        <L 23>
    var_30 = wp::floor(var_21);
    var_31 = wp::int(var_30);
    var_33 = &((var_l).map_w);
    var_36 = wp::load(var_33);
    var_35 = wp::sub(var_36, var_34);
    var_37 = wp::clamp(var_31, var_32, var_35);
    // a = wp.clamp(ft - float(i), 0.0, 1.0)                                                  <L 24>
    var_38 = wp::float(var_29);
    var_39 = wp::sub(var_10, var_38);
    var_42 = wp::clamp(var_39, var_40, var_41);
    // b = wp.clamp(fp - float(j), 0.0, 1.0)                                                  <L 25>
    var_43 = wp::float(var_37);
    var_44 = wp::sub(var_21, var_43);
    var_47 = wp::clamp(var_44, var_45, var_46);
    // w = l.map_w                                                                            <L 26>
    var_48 = &((var_l).map_w);
    var_50 = wp::load(var_48);
    var_49 = wp::copy(var_50);
    // v0 = (1.0 - b) * l.map[i * w + j] + b * l.map[i * w + j + 1]                           <L 27>
    var_52 = wp::sub(var_51, var_47);
    var_53 = &((var_l).map);
    var_54 = wp::mul(var_29, var_49);
    var_55 = wp::add(var_54, var_37);
    var_57 = wp::load(var_53);
    var_56 = wp::address(var_57, var_55);
    var_59 = wp::load(var_56);
    var_58 = wp::mul(var_52, var_59);
    var_60 = &((var_l).map);
    var_61 = wp::mul(var_29, var_49);
    var_62 = wp::add(var_61, var_37);
    var_64 = wp::add(var_62, var_63);
    var_66 = wp::load(var_60);
    var_65 = wp::address(var_66, var_64);
    var_68 = wp::load(var_65);
    var_67 = wp::mul(var_47, var_68);
    var_69 = wp::add(var_58, var_67);
    // v1 = (1.0 - b) * l.map[(i + 1) * w + j] + b * l.map[(i + 1) * w + j + 1]               <L 28>
    var_71 = wp::sub(var_70, var_47);
    var_72 = &((var_l).map);
    var_74 = wp::add(var_29, var_73);
    var_75 = wp::mul(var_74, var_49);
    var_76 = wp::add(var_75, var_37);
    var_78 = wp::load(var_72);
    var_77 = wp::address(var_78, var_76);
    var_80 = wp::load(var_77);
    var_79 = wp::mul(var_71, var_80);
    var_81 = &((var_l).map);
    var_83 = wp::add(var_29, var_82);
    var_84 = wp::mul(var_83, var_49);
    var_85 = wp::add(var_84, var_37);
    var_87 = wp::add(var_85, var_86);
    var_89 = wp::load(var_81);
    var_88 = wp::address(var_89, var_87);
    var_91 = wp::load(var_88);
    var_90 = wp::mul(var_47, var_91);
    var_92 = wp::add(var_79, var_90);
    // return (1.0 - a) * v0 + a * v1                                                         <L 29>
    var_94 = wp::sub(var_93, var_42);
    var_95 = wp::mul(var_94, var_69);
    var_96 = wp::mul(var_42, var_92);
    var_97 = wp::add(var_95, var_96);
    return var_97;
}


// /work/main/simulator/kernels/shaping.py:32
static wp::float32 shaping_factor_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_w_out)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    const wp::float32 var_4 = 1.0;
    wp::vec_t<3, wp::float32>* var_5;
    wp::float32 var_6;
    wp::vec_t<3, wp::float32> var_7;
    wp::float32 var_8;
    const wp::float32 var_9 = -1.0;
    const wp::float32 var_10 = 1.0;
    wp::float32 var_11;
    wp::float32 var_12;
    const wp::float32 var_13 = 1.0;
    wp::float32 var_14;
    wp::float32* var_15;
    const wp::float32 var_16 = 0.0;
    bool var_17;
    wp::float32 var_18;
    wp::vec_t<4, wp::float32>* var_19;
    const wp::int32 var_20 = 0;
    wp::float32 var_21;
    wp::vec_t<4, wp::float32> var_22;
    bool var_23;
    const wp::float32 var_24 = 0.0;
    const wp::float32 var_25 = 1.0;
    wp::vec_t<4, wp::float32>* var_26;
    const wp::int32 var_27 = 1;
    wp::float32 var_28;
    wp::vec_t<4, wp::float32> var_29;
    wp::float32 var_30;
    wp::float32 var_31;
    bool var_32;
    wp::vec_t<4, wp::float32>* var_33;
    const wp::int32 var_34 = 1;
    wp::float32 var_35;
    wp::vec_t<4, wp::float32> var_36;
    const wp::float32 var_37 = 0.0;
    bool var_38;
    bool var_39;
    wp::float32 var_40;
    wp::float32 var_41;
    wp::float32 var_42;
    const wp::float32 var_43 = 0.0;
    const wp::float32 var_44 = 1.0;
    wp::float32 var_45;
    const wp::float32 var_46 = 1.0;
    wp::float32 var_47;
    const wp::float32 var_48 = 3.0;
    const wp::float32 var_49 = 2.0;
    wp::float32 var_50;
    wp::float32 var_51;
    wp::float32 var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::float32 var_55;
    wp::vec_t<4, wp::float32>* var_56;
    const wp::int32 var_57 = 2;
    wp::float32 var_58;
    wp::vec_t<4, wp::float32> var_59;
    const wp::float32 var_60 = 0.0;
    bool var_61;
    wp::vec_t<4, wp::float32>* var_62;
    const wp::int32 var_63 = 3;
    wp::float32 var_64;
    wp::vec_t<4, wp::float32> var_65;
    const wp::float32 var_66 = 1.0;
    wp::float32 var_67;
    wp::float32 var_68;
    wp::vec_t<4, wp::float32>* var_69;
    const wp::int32 var_70 = 2;
    wp::float32 var_71;
    wp::vec_t<4, wp::float32> var_72;
    wp::float32 var_73;
    wp::float32 var_74;
    wp::float32 var_75;
    wp::float32 var_76;
    wp::float32 var_77;
    wp::float32* var_78;
    const wp::float32 var_79 = 0.0;
    bool var_80;
    wp::float32 var_81;
    wp::vec_t<3, wp::float32>* var_82;
    wp::float32 var_83;
    wp::vec_t<3, wp::float32> var_84;
    wp::vec_t<3, wp::float32>* var_85;
    wp::float32 var_86;
    wp::vec_t<3, wp::float32> var_87;
    wp::float32 var_88;
    const wp::float32 var_89 = 0.0;
    bool var_90;
    const wp::float32 var_91 = 2.0;
    const wp::float32 var_92 = 3.141592653589793;
    wp::float32 var_93;
    wp::float32 var_94;
    wp::float32 var_95;
    wp::float32* var_96;
    wp::float32 var_97;
    wp::float32 var_98;
    wp::float32 var_99;
    wp::float32 var_100;
    wp::float32 var_101;
    wp::float32 var_102;
    wp::float32 var_103;
    //---------
    // forward
    // def shaping_factor(l: LightRec, w_out: wp.vec3) -> float:                              <L 33>
    // if l.shaped == 0:                                                                      <L 41>
    var_0 = &((var_l).shaped);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return 1.0                                                                         <L 42>
        return var_4;
    }
    // cos_t = wp.clamp(-wp.dot(w_out, l.ez), -1.0, 1.0)                                      <L 43>
    var_5 = &((var_l).ez);
    var_7 = wp::load(var_5);
    var_6 = wp::dot(var_w_out, var_7);
    var_8 = wp::neg(var_6);
    var_11 = wp::clamp(var_8, var_9, var_10);
    // theta = wp.acos(cos_t)                                                                 <L 44>
    var_12 = wp::acos(var_11);
    // f = float(1.0)                                                                         <L 45>
    var_14 = wp::float(var_13);
    // if l.ies_scale <= 0.0:  # UsdLux: the cone "does not affect IES profiles"              <L 46>
    var_15 = &((var_l).ies_scale);
    var_18 = wp::load(var_15);
    var_17 = (var_18 <= var_16);
    if (var_17) {
        // cut = l.shaping[0]                                                                 <L 47>
        var_19 = &((var_l).shaping);
        var_22 = wp::load(var_19);
        var_21 = wp::extract(var_22, var_20);
        // if theta > cut:                                                                    <L 48>
        var_23 = (var_12 > var_21);
        if (var_23) {
            // return 0.0                                                                     <L 49>
            return var_24;
        }
        // start = cut * (1.0 - l.shaping[1])                                                 <L 50>
        var_26 = &((var_l).shaping);
        var_29 = wp::load(var_26);
        var_28 = wp::extract(var_29, var_27);
        var_30 = wp::sub(var_25, var_28);
        var_31 = wp::mul(var_21, var_30);
        // if l.shaping[1] > 0.0 and cut > start:                                             <L 51>
        var_33 = &((var_l).shaping);
        var_36 = wp::load(var_33);
        var_35 = wp::extract(var_36, var_34);
        var_38 = (var_35 > var_37);
        var_32 = var_38;
        if (var_32) {
            var_39 = (var_21 > var_31);
            var_32 = var_32 && var_39;
        }
        if (var_32) {
            // t = wp.clamp((theta - start) / (cut - start), 0.0, 1.0)                        <L 52>
            var_40 = wp::sub(var_12, var_31);
            var_41 = wp::sub(var_21, var_31);
            var_42 = wp::div(var_40, var_41);
            var_45 = wp::clamp(var_42, var_43, var_44);
            // f = 1.0 - t * t * (3.0 - 2.0 * t)                                              <L 53>
            var_47 = wp::mul(var_45, var_45);
            var_50 = wp::mul(var_49, var_45);
            var_51 = wp::sub(var_48, var_50);
            var_52 = wp::mul(var_47, var_51);
            var_53 = wp::sub(var_46, var_52);
        }
        var_54 = wp::where(var_32, var_53, var_14);
    }
    var_55 = wp::where(var_17, var_54, var_14);
    // if l.shaping[2] > 0.0:                                                                 <L 54>
    var_56 = &((var_l).shaping);
    var_59 = wp::load(var_56);
    var_58 = wp::extract(var_59, var_57);
    var_61 = (var_58 > var_60);
    if (var_61) {
        // tint = l.shaping[3]                                                                <L 55>
        var_62 = &((var_l).shaping);
        var_65 = wp::load(var_62);
        var_64 = wp::extract(var_65, var_63);
        // f = f * (tint + (1.0 - tint) * wp.pow(wp.abs(cos_t), l.shaping[2]))                <L 56>
        var_67 = wp::sub(var_66, var_64);
        var_68 = wp::abs(var_11);
        var_69 = &((var_l).shaping);
        var_72 = wp::load(var_69);
        var_71 = wp::extract(var_72, var_70);
        var_73 = wp::pow(var_68, var_71);
        var_74 = wp::mul(var_67, var_73);
        var_75 = wp::add(var_64, var_74);
        var_76 = wp::mul(var_55, var_75);
    }
    var_77 = wp::where(var_61, var_76, var_55);
    // if l.ies_scale > 0.0:                                                                  <L 57>
    var_78 = &((var_l).ies_scale);
    var_81 = wp::load(var_78);
    var_80 = (var_81 > var_79);
    if (var_80) {
        // phi = wp.atan2(wp.dot(w_out, l.ey), wp.dot(w_out, l.ex))                           <L 58>
        var_82 = &((var_l).ey);
        var_84 = wp::load(var_82);
        var_83 = wp::dot(var_w_out, var_84);
        var_85 = &((var_l).ex);
        var_87 = wp::load(var_85);
        var_86 = wp::dot(var_w_out, var_87);
        var_88 = wp::atan2(var_83, var_86);
        // if phi < 0.0:                                                                      <L 59>
        var_90 = (var_88 < var_89);
        if (var_90) {
            // phi = phi + 2.0 * PI                                                           <L 60>
            var_93 = wp::mul(var_91, var_92);
            var_94 = wp::add(var_88, var_93);
        }
        var_95 = wp::where(var_90, var_94, var_88);
        // f = f * l.ies_scale * ies_candela(l, wp.degrees(theta), wp.degrees(phi))           <L 61>
        var_96 = &((var_l).ies_scale);
        var_98 = wp::load(var_96);
        var_97 = wp::mul(var_77, var_98);
        var_99 = wp::degrees(var_12);
        var_100 = wp::degrees(var_95);
        var_101 = ies_candela_0(var_l, var_99, var_100);
        var_102 = wp::mul(var_97, var_101);
    }
    var_103 = wp::where(var_80, var_102, var_77);
    // return f                                                                               <L 62>
    return var_103;
}


// /work/main/simulator/kernels/estimators.py:335
static wp::vec_t<2, wp::float32> analytic_irradiance_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
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
    wp::array_t<LightRec_73c30c8a>* var_7;
    LightRec_73c30c8a* var_8;
    wp::array_t<LightRec_73c30c8a> var_9;
    LightRec_73c30c8a var_10;
    LightRec_73c30c8a var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::vec_t<3, wp::float32>* var_13;
    wp::vec_t<2, wp::float32> var_14;
    wp::vec_t<3, wp::float32> var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::int32* var_17;
    const wp::int32 var_18 = 0;
    bool var_19;
    wp::int32 var_20;
    wp::vec_t<3, wp::float32>* var_21;
    wp::vec_t<3, wp::float32>* var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::vec_t<3, wp::float32> var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::float32 var_27;
    wp::vec_t<2, wp::float32> var_28;
    wp::vec_t<2, wp::float32> var_29;
    wp::vec_t<2, wp::float32> var_30;
    //---------
    // forward
    // def analytic_irradiance(scene: SceneRec, s: SensorRec) -> wp.vec2:                     <L 336>
    // v = wp.vec2(0.0, 0.0)                                                                  <L 338>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    // for li in range(scene.n_lights):                                                       <L 339>
    var_3 = &((var_scene).n_lights);
    var_5 = wp::load(var_3);
    var_4 = wp::range(var_5);
    start_for_0:;
        if (iter_cmp(var_4) == 0) goto end_for_0;
        var_6 = wp::iter_next(var_4);
        // l = scene.lights[li]                                                               <L 340>
        var_7 = &((var_scene).lights);
        var_9 = wp::load(var_7);
        var_8 = wp::address(var_9, var_6);
        var_11 = wp::load(var_8);
        var_10 = wp::copy(var_11);
        // e = analytic_light(scene, li, s.position, s.normal)                                <L 341>
        var_12 = &((var_s).position);
        var_13 = &((var_s).normal);
        var_15 = wp::load(var_12);
        var_16 = wp::load(var_13);
        var_14 = analytic_light_0(var_scene, var_6, var_15, var_16);
        // if l.shaped != 0:  # the planner sends only shaped point lights here: E = I(ω)·cosψ/d²       <L 342>
        var_17 = &((var_10).shaped);
        var_20 = wp::load(var_17);
        var_19 = (var_20 != var_18);
        if (var_19) {
            // e = e * shaping_factor(l, wp.normalize(s.position - l.position))               <L 343>
            var_21 = &((var_s).position);
            var_22 = &((var_10).position);
            var_24 = wp::load(var_21);
            var_25 = wp::load(var_22);
            var_23 = wp::sub(var_24, var_25);
            var_26 = wp::normalize(var_23);
            var_27 = shaping_factor_0(var_10, var_26);
            var_28 = wp::mul(var_14, var_27);
        }
        var_29 = wp::where(var_19, var_28, var_14);
        // v += e                                                                             <L 344>
        var_30 = wp::add(var_2, var_29);
        wp::assign(var_2, var_30);
        goto start_for_0;
    end_for_0:;
    // return v                                                                               <L 345>
    return var_2;
}


// /work/main/simulator/kernels/closed_forms.py:185
static wp::float32 triangle_solid_angle_0(
    wp::vec_t<3, wp::float32> var_a,
    wp::vec_t<3, wp::float32> var_b,
    wp::vec_t<3, wp::float32> var_c)
{
    //---------
    // primal vars
    wp::float32 var_0;
    wp::float32 var_1;
    wp::float32 var_2;
    wp::vec_t<3, wp::float32> var_3;
    wp::float32 var_4;
    wp::float32 var_5;
    wp::float32 var_6;
    wp::float32 var_7;
    wp::float32 var_8;
    wp::float32 var_9;
    wp::float32 var_10;
    wp::float32 var_11;
    wp::float32 var_12;
    wp::float32 var_13;
    wp::float32 var_14;
    wp::float32 var_15;
    wp::float32 var_16;
    const wp::float32 var_17 = 2.0;
    wp::float32 var_18;
    wp::float32 var_19;
    //---------
    // forward
    // def triangle_solid_angle(a: wp.vec3, b: wp.vec3, c: wp.vec3) -> float:                 <L 186>
    // la = wp.length(a)                                                                      <L 189>
    var_0 = wp::length(var_a);
    // lb = wp.length(b)                                                                      <L 190>
    var_1 = wp::length(var_b);
    // lc = wp.length(c)                                                                      <L 191>
    var_2 = wp::length(var_c);
    // num = wp.abs(wp.dot(a, wp.cross(b, c)))                                                <L 192>
    var_3 = wp::cross(var_b, var_c);
    var_4 = wp::dot(var_a, var_3);
    var_5 = wp::abs(var_4);
    // den = la * lb * lc + wp.dot(a, b) * lc + wp.dot(a, c) * lb + wp.dot(b, c) * la         <L 193>
    var_6 = wp::mul(var_0, var_1);
    var_7 = wp::mul(var_6, var_2);
    var_8 = wp::dot(var_a, var_b);
    var_9 = wp::mul(var_8, var_2);
    var_10 = wp::add(var_7, var_9);
    var_11 = wp::dot(var_a, var_c);
    var_12 = wp::mul(var_11, var_1);
    var_13 = wp::add(var_10, var_12);
    var_14 = wp::dot(var_b, var_c);
    var_15 = wp::mul(var_14, var_0);
    var_16 = wp::add(var_13, var_15);
    // return 2.0 * wp.atan2(num, den)                                                        <L 194>
    var_18 = wp::atan2(var_5, var_16);
    var_19 = wp::mul(var_17, var_18);
    return var_19;
}


// /work/main/simulator/kernels/lights/point.py:36
static wp::vec_t<2, wp::float32> analytic_patch_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h)
{
    //---------
    // primal vars
    wp::vec_t<3, wp::float32>* var_0;
    wp::vec_t<3, wp::float32> var_1;
    wp::vec_t<3, wp::float32> var_2;
    wp::float32 var_3;
    const wp::float32 var_4 = 0.0;
    bool var_5;
    const wp::float32 var_6 = 0.0;
    const wp::float32 var_7 = 0.0;
    wp::vec_t<2, wp::float32> var_8;
    const wp::float32 var_9 = 0.5;
    wp::float32 var_10;
    wp::vec_t<3, wp::float32> var_11;
    const wp::float32 var_12 = 0.5;
    wp::float32 var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::vec_t<3, wp::float32>* var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32> var_17;
    wp::vec_t<3, wp::float32> var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::float32 var_24;
    wp::vec_t<3, wp::float32> var_25;
    wp::vec_t<3, wp::float32> var_26;
    wp::vec_t<3, wp::float32> var_27;
    wp::vec_t<3, wp::float32> var_28;
    wp::vec_t<3, wp::float32> var_29;
    wp::vec_t<3, wp::float32> var_30;
    wp::float32 var_31;
    wp::float32 var_32;
    wp::vec_t<2, wp::float32>* var_33;
    wp::float32 var_34;
    wp::float32 var_35;
    wp::vec_t<2, wp::float32> var_36;
    wp::vec_t<2, wp::float32> var_37;
    //---------
    // forward
    // def analytic_patch(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:       <L 37>
    // if wp.dot(l.position - c, n) <= 0.0:                                                   <L 41>
    var_0 = &((var_l).position);
    var_2 = wp::load(var_0);
    var_1 = wp::sub(var_2, var_c);
    var_3 = wp::dot(var_1, var_n);
    var_5 = (var_3 <= var_4);
    if (var_5) {
        // return wp.vec2(0.0, 0.0)                                                           <L 42>
        var_8 = wp::vec_t<2, wp::float32>(var_6, var_7);
        return var_8;
    }
    // hx = 0.5 * w * right                                                                   <L 43>
    var_10 = wp::mul(var_9, var_w);
    var_11 = wp::mul(var_10, var_right);
    // hy = 0.5 * h * up                                                                      <L 44>
    var_13 = wp::mul(var_12, var_h);
    var_14 = wp::mul(var_13, var_up);
    // r = c - l.position                                                                     <L 45>
    var_15 = &((var_l).position);
    var_17 = wp::load(var_15);
    var_16 = wp::sub(var_c, var_17);
    // omega = triangle_solid_angle(r - hx - hy, r + hx - hy, r + hx + hy) + triangle_solid_angle(       <L 46>
    var_18 = wp::sub(var_16, var_11);
    var_19 = wp::sub(var_18, var_14);
    var_20 = wp::add(var_16, var_11);
    var_21 = wp::sub(var_20, var_14);
    var_22 = wp::add(var_16, var_11);
    var_23 = wp::add(var_22, var_14);
    var_24 = triangle_solid_angle_0(var_19, var_21, var_23);
    // r - hx - hy, r + hx + hy, r - hx + hy                                                  <L 47>
    var_25 = wp::sub(var_16, var_11);
    var_26 = wp::sub(var_25, var_14);
    var_27 = wp::add(var_16, var_11);
    var_28 = wp::add(var_27, var_14);
    var_29 = wp::sub(var_16, var_11);
    var_30 = wp::add(var_29, var_14);
    var_31 = triangle_solid_angle_0(var_26, var_28, var_30);
    var_32 = wp::add(var_24, var_31);
    // return l.emission * (omega / (w * h))                                                  <L 49>
    var_33 = &((var_l).emission);
    var_34 = wp::mul(var_w, var_h);
    var_35 = wp::div(var_32, var_34);
    var_37 = wp::load(var_33);
    var_36 = wp::mul(var_37, var_35);
    return var_36;
}


// /work/main/simulator/kernels/lights/__init__.py:202
static wp::vec_t<2, wp::float32> _no_analytic_patch_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    const wp::float32 var_1 = 0.0;
    wp::vec_t<2, wp::float32> var_2;
    //---------
    // forward
    // def _no_analytic_patch(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:       <L 203>
    // return wp.vec2(0.0, 0.0)                                                               <L 204>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    return var_2;
}


// /work/main/simulator/kernels/lights/__init__.py:191
static wp::vec_t<2, wp::float32> _analytic_patch_link__locals__analytic_patch_kind_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_patch_kind(                                                               <L 192>
    // if l.kind == wp.static(k):                                                             <L 195>
    var_0 = &((var_l).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(l, c, n, right, up, w, h)                                   <L 196>
        var_4 = analytic_patch_0(var_l, var_c, var_n, var_right, var_up, var_w, var_h);
        return var_4;
    }
    // return wp.static(rest)(l, c, n, right, up, w, h)                                       <L 197>
    var_5 = _no_analytic_patch_0(var_l, var_c, var_n, var_right, var_up, var_w, var_h);
    return var_5;
}


// /work/main/simulator/kernels/lights/__init__.py:259
static wp::vec_t<2, wp::float32> analytic_patch_light_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h)
{
    //---------
    // primal vars
    wp::vec_t<2, wp::float32> var_0;
    //---------
    // forward
    // def analytic_patch_light(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:       <L 260>
    // return _analytic_patch_chain(l, c, n, right, up, w, h)                                 <L 263>
    var_0 = _analytic_patch_link__locals__analytic_patch_kind_0(var_l, var_c, var_n, var_right, var_up, var_w, var_h);
    return var_0;
}


// /work/main/simulator/kernels/estimators.py:348
static wp::vec_t<2, wp::float32> analytic_patch_1(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
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
    wp::array_t<LightRec_73c30c8a>* var_7;
    LightRec_73c30c8a* var_8;
    wp::array_t<LightRec_73c30c8a> var_9;
    wp::vec_t<3, wp::float32>* var_10;
    wp::vec_t<3, wp::float32>* var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::vec_t<3, wp::float32>* var_13;
    wp::float32* var_14;
    wp::float32* var_15;
    wp::vec_t<2, wp::float32> var_16;
    LightRec_73c30c8a var_17;
    wp::vec_t<3, wp::float32> var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32> var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::float32 var_22;
    wp::float32 var_23;
    wp::vec_t<2, wp::float32> var_24;
    //---------
    // forward
    // def analytic_patch(scene: SceneRec, s: SensorRec) -> wp.vec2:                          <L 349>
    // v = wp.vec2(0.0, 0.0)                                                                  <L 352>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    // for li in range(scene.n_lights):                                                       <L 353>
    var_3 = &((var_scene).n_lights);
    var_5 = wp::load(var_3);
    var_4 = wp::range(var_5);
    start_for_0:;
        if (iter_cmp(var_4) == 0) goto end_for_0;
        var_6 = wp::iter_next(var_4);
        // v += analytic_patch_light(scene.lights[li], s.position, s.normal, s.right, s.up, s.width, s.height)       <L 354>
        var_7 = &((var_scene).lights);
        var_9 = wp::load(var_7);
        var_8 = wp::address(var_9, var_6);
        var_10 = &((var_s).position);
        var_11 = &((var_s).normal);
        var_12 = &((var_s).right);
        var_13 = &((var_s).up);
        var_14 = &((var_s).width);
        var_15 = &((var_s).height);
        var_17 = wp::load(var_8);
        var_18 = wp::load(var_10);
        var_19 = wp::load(var_11);
        var_20 = wp::load(var_12);
        var_21 = wp::load(var_13);
        var_22 = wp::load(var_14);
        var_23 = wp::load(var_15);
        var_16 = analytic_patch_light_0(var_17, var_18, var_19, var_20, var_21, var_22, var_23);
        var_24 = wp::add(var_2, var_16);
        wp::assign(var_2, var_24);
        goto start_for_0;
    end_for_0:;
    // return v                                                                               <L 355>
    return var_2;
}


// /work/main/simulator/kernels/estimators.py:301
static wp::vec_t<2, wp::float32> analytic_cylinder_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    wp::int32 var_half)
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
    wp::array_t<LightRec_73c30c8a>* var_7;
    LightRec_73c30c8a* var_8;
    wp::array_t<LightRec_73c30c8a> var_9;
    LightRec_73c30c8a var_10;
    LightRec_73c30c8a var_11;
    wp::vec_t<3, wp::float32>* var_12;
    wp::vec_t<3, wp::float32>* var_13;
    wp::vec_t<3, wp::float32> var_14;
    wp::vec_t<3, wp::float32> var_15;
    wp::vec_t<3, wp::float32> var_16;
    wp::vec_t<3, wp::float32>* var_17;
    wp::float32 var_18;
    wp::vec_t<3, wp::float32> var_19;
    wp::vec_t<3, wp::float32>* var_20;
    wp::vec_t<3, wp::float32> var_21;
    wp::vec_t<3, wp::float32> var_22;
    wp::vec_t<3, wp::float32> var_23;
    wp::float32 var_24;
    const wp::float32 var_25 = 0.0;
    bool var_26;
    wp::vec_t<3, wp::float32> var_27;
    wp::vec_t<3, wp::float32>* var_28;
    wp::vec_t<2, wp::float32> var_29;
    wp::vec_t<3, wp::float32> var_30;
    wp::int32* var_31;
    const wp::int32 var_32 = 0;
    bool var_33;
    wp::int32 var_34;
    wp::vec_t<3, wp::float32>* var_35;
    wp::vec_t<3, wp::float32>* var_36;
    wp::vec_t<3, wp::float32> var_37;
    wp::vec_t<3, wp::float32> var_38;
    wp::vec_t<3, wp::float32> var_39;
    wp::vec_t<3, wp::float32> var_40;
    wp::float32 var_41;
    wp::vec_t<2, wp::float32> var_42;
    wp::vec_t<2, wp::float32> var_43;
    const wp::float32 var_44 = 1.0;
    const wp::float32 var_45 = 3.141592653589793;
    wp::float32 var_46;
    const wp::int32 var_47 = 0;
    bool var_48;
    const wp::float32 var_49 = 1.0;
    wp::vec_t<3, wp::float32>* var_50;
    wp::float32 var_51;
    wp::vec_t<3, wp::float32> var_52;
    wp::float32 var_53;
    wp::float32 var_54;
    wp::float32 var_55;
    wp::vec_t<2, wp::float32> var_56;
    wp::vec_t<2, wp::float32> var_57;
    //---------
    // forward
    // def analytic_cylinder(scene: SceneRec, s: SensorRec, half: int) -> wp.vec2:            <L 302>
    // v = wp.vec2(0.0, 0.0)                                                                  <L 306>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    // for li in range(scene.n_lights):                                                       <L 307>
    var_3 = &((var_scene).n_lights);
    var_5 = wp::load(var_3);
    var_4 = wp::range(var_5);
    start_for_0:;
        if (iter_cmp(var_4) == 0) goto end_for_0;
        var_6 = wp::iter_next(var_4);
        // l = scene.lights[li]                                                               <L 308>
        var_7 = &((var_scene).lights);
        var_9 = wp::load(var_7);
        var_8 = wp::address(var_9, var_6);
        var_11 = wp::load(var_8);
        var_10 = wp::copy(var_11);
        // w = l.position - s.position                                                        <L 309>
        var_12 = &((var_10).position);
        var_13 = &((var_s).position);
        var_15 = wp::load(var_12);
        var_16 = wp::load(var_13);
        var_14 = wp::sub(var_15, var_16);
        // across = w - wp.dot(w, s.up) * s.up                                                <L 310>
        var_17 = &((var_s).up);
        var_19 = wp::load(var_17);
        var_18 = wp::dot(var_14, var_19);
        var_20 = &((var_s).up);
        var_22 = wp::load(var_20);
        var_21 = wp::mul(var_18, var_22);
        var_23 = wp::sub(var_14, var_21);
        // la = wp.length(across)                                                             <L 311>
        var_24 = wp::length(var_23);
        // if la <= 0.0:                                                                      <L 312>
        var_26 = (var_24 <= var_25);
        if (var_26) {
            // continue  # on the axis: sinθ = 0                                              <L 313>
            goto start_for_0;
        }
        // n = across / la                                                                    <L 314>
        var_27 = wp::div(var_23, var_24);
        // e = analytic_light(scene, li, s.position, n)                                       <L 315>
        var_28 = &((var_s).position);
        var_30 = wp::load(var_28);
        var_29 = analytic_light_0(var_scene, var_6, var_30, var_27);
        // if l.shaped != 0:                                                                  <L 316>
        var_31 = &((var_10).shaped);
        var_34 = wp::load(var_31);
        var_33 = (var_34 != var_32);
        if (var_33) {
            // e = e * shaping_factor(l, wp.normalize(s.position - l.position))               <L 317>
            var_35 = &((var_s).position);
            var_36 = &((var_10).position);
            var_38 = wp::load(var_35);
            var_39 = wp::load(var_36);
            var_37 = wp::sub(var_38, var_39);
            var_40 = wp::normalize(var_37);
            var_41 = shaping_factor_0(var_10, var_40);
            var_42 = wp::mul(var_29, var_41);
        }
        var_43 = wp::where(var_33, var_42, var_29);
        // f = 1.0 / PI                                                                       <L 318>
        var_46 = wp::div(var_44, var_45);
        // if half != 0:                                                                      <L 319>
        var_48 = (var_half != var_47);
        if (var_48) {
            // f = (1.0 + wp.dot(n, s.right)) / PI                                            <L 320>
            var_50 = &((var_s).right);
            var_52 = wp::load(var_50);
            var_51 = wp::dot(var_27, var_52);
            var_53 = wp::add(var_49, var_51);
            var_54 = wp::div(var_53, var_45);
        }
        var_55 = wp::where(var_48, var_54, var_46);
        // v += f * e                                                                         <L 321>
        var_56 = wp::mul(var_55, var_43);
        var_57 = wp::add(var_2, var_56);
        wp::assign(var_2, var_57);
        goto start_for_0;
    end_for_0:;
    // return v                                                                               <L 322>
    return var_2;
}


// /work/main/simulator/kernels/estimators.py:325
static wp::vec_t<2, wp::float32> analytic_cylindrical_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 0;
    wp::vec_t<2, wp::float32> var_1;
    //---------
    // forward
    // def analytic_cylindrical(scene: SceneRec, s: SensorRec) -> wp.vec2:                    <L 326>
    // return analytic_cylinder(scene, s, 0)                                                  <L 327>
    var_1 = analytic_cylinder_0(var_scene, var_s, var_0);
    return var_1;
}


// /work/main/simulator/kernels/estimators.py:330
static wp::vec_t<2, wp::float32> analytic_semicylindrical_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    const wp::int32 var_0 = 1;
    wp::vec_t<2, wp::float32> var_1;
    //---------
    // forward
    // def analytic_semicylindrical(scene: SceneRec, s: SensorRec) -> wp.vec2:                <L 331>
    // return analytic_cylinder(scene, s, 1)                                                  <L 332>
    var_1 = analytic_cylinder_0(var_scene, var_s, var_0);
    return var_1;
}


// /work/main/simulator/kernels/estimators.py:429
static wp::vec_t<2, wp::float32> _no_analytic_1(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    const wp::float32 var_0 = 0.0;
    const wp::float32 var_1 = 0.0;
    wp::vec_t<2, wp::float32> var_2;
    //---------
    // forward
    // def _no_analytic(scene: SceneRec, s: SensorRec) -> wp.vec2:                            <L 430>
    // return wp.vec2(0.0, 0.0)                                                               <L 431>
    var_2 = wp::vec_t<2, wp::float32>(var_0, var_1);
    return var_2;
}


// /work/main/simulator/kernels/estimators.py:420
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_7(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 5;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, s: SensorRec) -> wp.vec2:                           <L 421>
    // if s.kind == wp.static(k):                                                             <L 422>
    var_0 = &((var_s).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, s)                                                   <L 423>
        var_4 = analytic_semicylindrical_0(var_scene, var_s);
        return var_4;
    }
    // return wp.static(rest)(scene, s)                                                       <L 424>
    var_5 = _no_analytic_1(var_scene, var_s);
    return var_5;
}


// /work/main/simulator/kernels/estimators.py:420
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_8(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 4;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, s: SensorRec) -> wp.vec2:                           <L 421>
    // if s.kind == wp.static(k):                                                             <L 422>
    var_0 = &((var_s).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, s)                                                   <L 423>
        var_4 = analytic_cylindrical_0(var_scene, var_s);
        return var_4;
    }
    // return wp.static(rest)(scene, s)                                                       <L 424>
    var_5 = _analytic_link__locals__analytic_kind_7(var_scene, var_s);
    return var_5;
}


// /work/main/simulator/kernels/estimators.py:420
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_9(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 2;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, s: SensorRec) -> wp.vec2:                           <L 421>
    // if s.kind == wp.static(k):                                                             <L 422>
    var_0 = &((var_s).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, s)                                                   <L 423>
        var_4 = analytic_patch_1(var_scene, var_s);
        return var_4;
    }
    // return wp.static(rest)(scene, s)                                                       <L 424>
    var_5 = _analytic_link__locals__analytic_kind_8(var_scene, var_s);
    return var_5;
}


// /work/main/simulator/kernels/estimators.py:420
static wp::vec_t<2, wp::float32> _analytic_link__locals__analytic_kind_10(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    wp::int32* var_0;
    const wp::int32 var_1 = 0;
    bool var_2;
    wp::int32 var_3;
    wp::vec_t<2, wp::float32> var_4;
    wp::vec_t<2, wp::float32> var_5;
    //---------
    // forward
    // def analytic_kind(scene: SceneRec, s: SensorRec) -> wp.vec2:                           <L 421>
    // if s.kind == wp.static(k):                                                             <L 422>
    var_0 = &((var_s).kind);
    var_3 = wp::load(var_0);
    var_2 = (var_3 == var_1);
    if (var_2) {
        // return wp.static(hook)(scene, s)                                                   <L 423>
        var_4 = analytic_irradiance_0(var_scene, var_s);
        return var_4;
    }
    // return wp.static(rest)(scene, s)                                                       <L 424>
    var_5 = _analytic_link__locals__analytic_kind_9(var_scene, var_s);
    return var_5;
}


// /work/main/simulator/kernels/estimators.py:439
static wp::vec_t<2, wp::float32> analytic_sensor_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s)
{
    //---------
    // primal vars
    wp::vec_t<2, wp::float32> var_0;
    //---------
    // forward
    // def analytic_sensor(scene: SceneRec, s: SensorRec) -> wp.vec2:                         <L 440>
    // return _analytic_chain(scene, s)                                                       <L 442>
    var_0 = _analytic_link__locals__analytic_kind_10(var_scene, var_s);
    return var_0;
}


// /work/main/simulator/kernels/closed_forms.py:39
static void adj_point_irradiance_0(
    wp::vec_t<3, wp::float32> var_light_pos,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_light_pos,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/point.py:31
static void adj_analytic_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/closed_forms.py:50
static void adj_cap_irradiance_0(
    wp::vec_t<3, wp::float32> var_axis,
    wp::float32 var_sin2_sigma,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_axis,
    wp::float32 & adj_sin2_sigma,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/sphere.py:77
static void adj_analytic_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
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


// /work/main/simulator/kernels/lights/rect.py:63
static void adj_analytic_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/closed_forms.py:152
static void adj_disk_irradiance_0(
    wp::vec_t<3, wp::float32> var_centre,
    wp::vec_t<3, wp::float32> var_ex,
    wp::vec_t<3, wp::float32> var_ey,
    wp::float32 var_radius,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> & adj_centre,
    wp::vec_t<3, wp::float32> & adj_ex,
    wp::vec_t<3, wp::float32> & adj_ey,
    wp::float32 & adj_radius,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/disk.py:37
static void adj_analytic_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/distant.py:50
static void adj_analytic_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/dome.py:241
static void adj_analytic_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
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


// /work/main/simulator/kernels/lights/emissive.py:198
static void adj_analytic_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:185
static void adj__no_analytic_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_0(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_1(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_2(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_3(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_4(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_5(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:176
static void adj__analytic_link__locals__analytic_kind_6(
    SceneRec_19d73428 var_scene,
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:252
static void adj_analytic_light_0(
    SceneRec_19d73428 var_scene,
    wp::int32 var_li,
    wp::vec_t<3, wp::float32> var_p,
    wp::vec_t<3, wp::float32> var_n,
    SceneRec_19d73428 & adj_scene,
    wp::int32 & adj_li,
    wp::vec_t<3, wp::float32> & adj_p,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/shaping.py:14
static void adj_ies_candela_0(
    LightRec_73c30c8a var_l,
    wp::float32 var_theta_deg,
    wp::float32 var_phi_deg,
    LightRec_73c30c8a & adj_l,
    wp::float32 & adj_theta_deg,
    wp::float32 & adj_phi_deg,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/shaping.py:32
static void adj_shaping_factor_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_w_out,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_w_out,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:335
static void adj_analytic_irradiance_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/closed_forms.py:185
static void adj_triangle_solid_angle_0(
    wp::vec_t<3, wp::float32> var_a,
    wp::vec_t<3, wp::float32> var_b,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> & adj_a,
    wp::vec_t<3, wp::float32> & adj_b,
    wp::vec_t<3, wp::float32> & adj_c,
    wp::float32 & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/point.py:36
static void adj_analytic_patch_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_c,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_right,
    wp::vec_t<3, wp::float32> & adj_up,
    wp::float32 & adj_w,
    wp::float32 & adj_h,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:202
static void adj__no_analytic_patch_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_c,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_right,
    wp::vec_t<3, wp::float32> & adj_up,
    wp::float32 & adj_w,
    wp::float32 & adj_h,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:191
static void adj__analytic_patch_link__locals__analytic_patch_kind_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_c,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_right,
    wp::vec_t<3, wp::float32> & adj_up,
    wp::float32 & adj_w,
    wp::float32 & adj_h,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/lights/__init__.py:259
static void adj_analytic_patch_light_0(
    LightRec_73c30c8a var_l,
    wp::vec_t<3, wp::float32> var_c,
    wp::vec_t<3, wp::float32> var_n,
    wp::vec_t<3, wp::float32> var_right,
    wp::vec_t<3, wp::float32> var_up,
    wp::float32 var_w,
    wp::float32 var_h,
    LightRec_73c30c8a & adj_l,
    wp::vec_t<3, wp::float32> & adj_c,
    wp::vec_t<3, wp::float32> & adj_n,
    wp::vec_t<3, wp::float32> & adj_right,
    wp::vec_t<3, wp::float32> & adj_up,
    wp::float32 & adj_w,
    wp::float32 & adj_h,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:348
static void adj_analytic_patch_1(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:301
static void adj_analytic_cylinder_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    wp::int32 var_half,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::int32 & adj_half,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:325
static void adj_analytic_cylindrical_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:330
static void adj_analytic_semicylindrical_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:429
static void adj__no_analytic_1(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:420
static void adj__analytic_link__locals__analytic_kind_7(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:420
static void adj__analytic_link__locals__analytic_kind_8(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:420
static void adj__analytic_link__locals__analytic_kind_9(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:420
static void adj__analytic_link__locals__analytic_kind_10(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}


// /work/main/simulator/kernels/estimators.py:439
static void adj_analytic_sensor_0(
    SceneRec_19d73428 var_scene,
    SensorRec_d6d15068 var_s,
    SceneRec_19d73428 & adj_scene,
    SensorRec_d6d15068 & adj_s,
    wp::vec_t<2, wp::float32> & adj_ret)
{
	// reverse mode disabled (no backward-enabled kernel depends on this function)
}

struct wp_args_analytic_kernel_819bcd18 {
    SceneRec_19d73428 scene;
    wp::array_t<SensorRec_d6d15068> sensors;
    wp::array_t<wp::int32> sensor_ids;
    wp::array_t<wp::vec_t<2, wp::float64>> out_value;
};


template <bool wp_linear_contiguous>
static void analytic_kernel_819bcd18_cpu_kernel_forward(
    wp::launch_bounds_t<1> dim,
    size_t task_index,
    wp_args_analytic_kernel_819bcd18 *_wp_args)
{
    static constexpr bool wp_linear_tid = wp_linear_contiguous;
    wp_args_analytic_kernel_819bcd18 wp_contiguous_args;
    if constexpr (wp_linear_contiguous)
    {
        wp_contiguous_args = *_wp_args;
        wp_contiguous_args.sensors.strides[0] = sizeof(SensorRec_d6d15068);
        wp_contiguous_args.sensor_ids.strides[0] = sizeof(wp::int32);
        wp_contiguous_args.out_value.strides[0] = sizeof(wp::vec_t<2, wp::float64>);
        _wp_args = &wp_contiguous_args;
    }
    //---------
    // argument vars
    SceneRec_19d73428 var_scene = _wp_args->scene;
    wp::array_t<SensorRec_d6d15068> var_sensors = _wp_args->sensors;
    wp::array_t<wp::int32> var_sensor_ids = _wp_args->sensor_ids;
    wp::array_t<wp::vec_t<2, wp::float64>> var_out_value = _wp_args->out_value;
    //---------
    // primal vars
    wp::int32 var_0;
    wp::int32* var_1;
    wp::int32 var_2;
    SensorRec_d6d15068* var_3;
    wp::vec_t<2, wp::float32> var_4;
    SensorRec_d6d15068 var_5;
    const wp::int32 var_6 = 0;
    wp::float32 var_7;
    wp::float64 var_8;
    const wp::int32 var_9 = 1;
    wp::float32 var_10;
    wp::float64 var_11;
    wp::vec_t<2, wp::float64> var_12;
    //---------
    // forward
    // def analytic_kernel(                                                                   <L 1378>
    // t = wp.tid()                                                                           <L 1386>
    var_0 = builtin_tid1d();
    // v = analytic_sensor(scene, sensors[sensor_ids[t]])                                     <L 1387>
    var_1 = wp::address(var_sensor_ids, var_0);
    var_2 = wp::load(var_1);
    var_3 = wp::address(var_sensors, var_2);
    var_5 = wp::load(var_3);
    var_4 = analytic_sensor_0(var_scene, var_5);
    // out_value[t] = wp.vec2d(wp.float64(v[0]), wp.float64(v[1]))                            <L 1388>
    var_7 = wp::extract(var_4, var_6);
    var_8 = wp::float64(var_7);
    var_10 = wp::extract(var_4, var_9);
    var_11 = wp::float64(var_10);
    var_12 = wp::vec_t<2, wp::float64>(var_8, var_11);
    wp::array_store(var_out_value, var_0, var_12);
}



template <bool wp_linear_contiguous>
static WP_FORCEINLINE void analytic_kernel_819bcd18_cpu_forward_tasks(
    wp::launch_bounds_t<1> *dim,
    wp_args_analytic_kernel_819bcd18 *_wp_args)
{
    for (size_t task_index = 0; task_index < dim->size; ++task_index)
    {
        analytic_kernel_819bcd18_cpu_kernel_forward<wp_linear_contiguous>(*dim, task_index, _wp_args);
    }
}

static WP_FORCEINLINE void analytic_kernel_819bcd18_cpu_forward_dispatch(
    wp::launch_bounds_t<1> *dim,
    wp_args_analytic_kernel_819bcd18 *_wp_args)
{
    wp::tile_shared_storage_t tile_mem;
#if defined(WP_ENABLE_TILES_IN_STACK_MEMORY)
    wp::shared_tile_storage = &tile_mem;
#endif

    const bool wp_linear_contiguous = dim->coord_mult == 1 && ((_wp_args->sensors.strides[0] == (int)sizeof(SensorRec_d6d15068)) & (_wp_args->sensor_ids.strides[0] == (int)sizeof(wp::int32)) & (_wp_args->out_value.strides[0] == (int)sizeof(wp::vec_t<2, wp::float64>)));
    if (wp_linear_contiguous)
        analytic_kernel_819bcd18_cpu_forward_tasks<true>(dim, _wp_args);
    else
        analytic_kernel_819bcd18_cpu_forward_tasks<false>(dim, _wp_args);
}

extern "C" {

// Python CPU entry points
WP_API void analytic_kernel_819bcd18_cpu_forward(
    wp::launch_bounds_t<1> *dim,
    wp_args_analytic_kernel_819bcd18 *_wp_args)
{
    analytic_kernel_819bcd18_cpu_forward_dispatch(dim, _wp_args);
}

} // extern C

