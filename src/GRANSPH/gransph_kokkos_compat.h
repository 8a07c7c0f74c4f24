/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: the LAMMPS KOKKOS-package API differences the /kk styles meet, in
   one place (gransph_lammps_compat.h has the plain ones and the version macro).

   - kokkos_type.h was rewritten after 2021 (KK_FLOAT/KK_ACC_FLOAT, TransformView
     atom arrays): the view types of the atom arrays we read and write are named
     here, per device, as GRANSPHCompat::KokkosTypes<DeviceType>;
   - the forward-communication hooks of a Kokkos fix changed name and signature
     (one send list per swap, the buffer type): GRANSPH_KOKKOS_FIX_FORWARD_COMM
     declares the hooks of the version and forwards them to two version-free
     members, pack_forward_comm_device(n, SendList, buf) and
     unpack_forward_comm_device(n, first, buf);
   - neighbour requests: NeighRequest's fields became protected
     (kokkos_full_list()).
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KOKKOS_COMPAT_H
#define LMP_GRANSPH_KOKKOS_COMPAT_H

#include "gransph_lammps_compat.h"
#include "kokkos_base.h"
#include "kokkos_type.h"

#include <type_traits>

// 1 for the rewritten kokkos_type.h and the KokkosBase forward-comm hooks of
// current LAMMPS (tested: 4 Jul 2026); 0 for 29 Sep 2021
#define GRANSPH_KOKKOS_NEW_API (GRANSPH_LAMMPS_VERSION >= 20250000)

namespace LAMMPS_NS {
namespace GRANSPHCompat {

  template <class DeviceType> struct KokkosTypes {
    typedef ArrayTypes<DeviceType> AT;
#if GRANSPH_KOKKOS_NEW_API
    typedef typename AT::t_kkfloat_1d_3_lr t_x;                  // atom->x
    typedef typename AT::t_kkfloat_1d_3 t_v;                     // atom->v
    typedef typename AT::t_kkacc_1d_3_randomread t_f_const;      // atom->f, read only
    typedef typename AT::t_kkfloat_1d_randomread t_mass_const;   // atom->mass, rmass
    typedef typename AT::t_double_2d_lr t_state;                 // our per-atom state
    typedef DAT::tdual_double_2d_lr tdual_state;
    typedef DAT::ttransform_kkacc_1d_6 tdual_virial;             // pair->vatom
    typedef DAT::tdual_double_1d tdual_comm_buffer;
    // the atoms a swap of forward communication sends
    struct SendList {
      typename AT::t_int_1d list;
      KOKKOS_INLINE_FUNCTION int operator()(int i) const { return list(i); }
    };
#else
    typedef typename AT::t_x_array t_x;
    typedef typename AT::t_v_array t_v;
    typedef typename AT::t_f_array_randomread t_f_const;
    typedef typename AT::t_float_1d_randomread t_mass_const;
    typedef typename AT::t_float_2d t_state;
    typedef DAT::tdual_float_2d tdual_state;
    typedef DAT::tdual_virial_array tdual_virial;
    typedef DAT::tdual_xfloat_1d tdual_comm_buffer;
    struct SendList {
      typename AT::t_int_2d list;
      int iswap;
      KOKKOS_INLINE_FUNCTION int operator()(int i) const { return list(iswap, i); }
    };
#endif
    typedef typename AT::t_int_1d_randomread t_int_const;        // atom->mask, type
  };

  // the host-side DualViews of the state, whatever DeviceType the style runs on
  typedef KokkosTypes<LMPDeviceType>::tdual_state tdual_state;
  typedef KokkosTypes<LMPDeviceType>::tdual_virial tdual_virial;
  typedef KokkosTypes<LMPDeviceType>::tdual_comm_buffer tdual_comm_buffer;

  // make the neighbour list the last init_style() requested for this pair a full
  // list built on DeviceType
  template <class DeviceType> void kokkos_full_list(Neighbor *neighbor, Pair *pair)
  {
    constexpr bool on_device = std::is_same<DeviceType, LMPDeviceType>::value;
    constexpr bool on_host = std::is_same<DeviceType, LMPHostType>::value && !on_device;
#if GRANSPH_LAMMPS_NEW_API
    NeighRequest *request = neighbor->find_request(pair);
    request->set_kokkos_host(on_host);
    request->set_kokkos_device(on_device);
    request->enable_full();
#else
    (void) pair;
    NeighRequest *request = neighbor->requests[neighbor->nrequest - 1];
    request->half = 0;
    request->full = 1;
    request->newton = 0;
    request->kokkos_host = on_host;
    request->kokkos_device = on_device;
#endif
  }

}    // namespace GRANSPHCompat
}    // namespace LAMMPS_NS

// In the class of a Kokkos fix (with typedef AT::... and a DeviceType): the
// forward-communication hooks of this LAMMPS version, forwarding to
//   int pack_forward_comm_device(int n, const SendList &list, tdual_comm_buffer &buf);
//   void unpack_forward_comm_device(int n, int first, tdual_comm_buffer &buf);
#if GRANSPH_KOKKOS_NEW_API
#define GRANSPH_KOKKOS_FIX_FORWARD_COMM                                                         \
  int pack_forward_comm_kokkos(int n, DAT::tdual_int_1d k_sendlist,                           \
                               DAT::tdual_double_1d &k_buf, int, int *) override               \
  {                                                                                            \
    return pack_forward_comm_device(n, {k_sendlist.template view<DeviceType>()}, k_buf);      \
  }                                                                                            \
  void unpack_forward_comm_kokkos(int n, int first, DAT::tdual_double_1d &k_buf) override     \
  {                                                                                            \
    unpack_forward_comm_device(n, first, k_buf);                                               \
  }
#else
#define GRANSPH_KOKKOS_FIX_FORWARD_COMM                                                         \
  int pack_forward_comm_fix_kokkos(int n, DAT::tdual_int_2d k_sendlist, int iswap,            \
                                   DAT::tdual_xfloat_1d &k_buf, int, int *) override           \
  {                                                                                            \
    return pack_forward_comm_device(n, {k_sendlist.template view<DeviceType>(), iswap}, k_buf); \
  }                                                                                            \
  void unpack_forward_comm_fix_kokkos(int n, int first, DAT::tdual_xfloat_1d &k_buf) override \
  {                                                                                            \
    unpack_forward_comm_device(n, first, k_buf);                                               \
  }
#endif

#endif
