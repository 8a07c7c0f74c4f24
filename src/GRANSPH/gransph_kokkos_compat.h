/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the LAMMPS KOKKOS-package API differences the /kk styles meet, in
   one place (gransph_lammps_compat.h has the plain ones and the version macro),
   each explained where it is defined: the atom arrays' view types, neighbour
   requests, moving a fix's per-atom arrays on the device, forward communication.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KOKKOS_COMPAT_H
#define LMP_GRANSPH_KOKKOS_COMPAT_H

#include "fix.h"
#include "gransph_lammps_compat.h"
#include "kokkos_base.h"
#include "kokkos_type.h"

#include <initializer_list>
#include <type_traits>

// 1 for the rewritten kokkos_type.h and the KokkosBase forward-comm hooks of
// current LAMMPS (tested: 4 Jul 2026); 0 for 29 Sep 2021
#define GRANSPH_KOKKOS_NEW_API (GRANSPH_LAMMPS_VERSION >= 20250000)

namespace LAMMPS_NS {
namespace GRANSPHCompat {

  // the view types of the atom arrays we read and write, per device: kokkos_type.h was
  // rewritten after 2021 (KK_FLOAT/KK_ACC_FLOAT, TransformView atom arrays)
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
  // list built on DeviceType (NeighRequest's fields became protected after 2021)
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

#if GRANSPH_KOKKOS_NEW_API
  // Per-atom rows held in 2-D DualViews (tdual_state) that move with their atoms on
  // the device, in the buffer layout of CommKokkos::exchange_device (as LAMMPS' own
  // fix spring/self/kk): the nsend offsets of the atoms' data, then each atom's row.
  template <class DeviceType> struct DeviceExchange {
    typedef ArrayTypes<DeviceType> AT;

    // the three arrays on DeviceType, before and after a kernel that moves their rows
    static void sync_rows(tdual_state &k_a, tdual_state &k_b, tdual_state &k_c)
    {
      for (tdual_state *k : {&k_a, &k_b, &k_c}) k->template sync<DeviceType>();
    }
    static void modify_rows(tdual_state &k_a, tdual_state &k_b, tdual_state &k_c)
    {
      for (tdual_state *k : {&k_a, &k_b, &k_c}) k->template modify<DeviceType>();
    }
    // the exchange buffer as one flat array of doubles
    static typename AT::t_double_1d_um flat(DAT::tdual_double_2d_lr &k_buf)
    {
      k_buf.template sync<DeviceType>();
      return typename AT::t_double_1d_um(k_buf.template view<DeviceType>().data(),
                                         k_buf.extent(0) * k_buf.extent(1));
    }

    static int pack(int nsend, DAT::tdual_double_2d_lr &k_buf, DAT::tdual_int_1d k_sendlist,
                    DAT::tdual_int_1d k_copylist, ExecutionSpace space, tdual_state &k_a,
                    tdual_state &k_b, tdual_state &k_c)
    {
      k_sendlist.template sync<DeviceType>();
      k_copylist.template sync<DeviceType>();
      sync_rows(k_a, k_b, k_c);
      const auto buf = flat(k_buf);
      const auto sendlist = k_sendlist.template view<DeviceType>();
      const auto copylist = k_copylist.template view<DeviceType>();
      const auto a = k_a.template view<DeviceType>();
      const auto b = k_b.template view<DeviceType>();
      const auto c = k_c.template view<DeviceType>();
      const int na = a.extent(1), nb = b.extent(1), nc = c.extent(1), row = na + nb + nc;
      Kokkos::parallel_for(
          Kokkos::RangePolicy<DeviceType>(0, nsend), LAMMPS_LAMBDA(const int s) {
            const int i = sendlist(s);
            int m = nsend + s * row;
            buf(s) = m;
            for (int k = 0; k < na; ++k) buf(m++) = a(i, k);
            for (int k = 0; k < nb; ++k) buf(m++) = b(i, k);
            for (int k = 0; k < nc; ++k) buf(m++) = c(i, k);
            // the atom leaving makes a hole that a staying atom fills
            const int j = copylist(s);
            if (j > -1) {
              for (int k = 0; k < na; ++k) a(i, k) = a(j, k);
              for (int k = 0; k < nb; ++k) b(i, k) = b(j, k);
              for (int k = 0; k < nc; ++k) c(i, k) = c(j, k);
            }
          });
      k_buf.template modify<DeviceType>();
      if (space == Host)
        k_buf.sync_host();
      else
        k_buf.sync_device();
      modify_rows(k_a, k_b, k_c);
      return nsend * (row + 1);
    }

    static void unpack(DAT::tdual_double_2d_lr &k_buf, DAT::tdual_int_1d &k_indices, int nrecv,
                       int nrecv1, int nextrarecv1, tdual_state &k_a, tdual_state &k_b,
                       tdual_state &k_c)
    {
      k_indices.template sync<DeviceType>();
      sync_rows(k_a, k_b, k_c);
      const auto buf = flat(k_buf);
      const auto indices = k_indices.template view<DeviceType>();
      const auto a = k_a.template view<DeviceType>();
      const auto b = k_b.template view<DeviceType>();
      const auto c = k_c.template view<DeviceType>();
      const int na = a.extent(1), nb = b.extent(1), nc = c.extent(1);
      Kokkos::parallel_for(
          Kokkos::RangePolicy<DeviceType>(0, nrecv), LAMMPS_LAMBDA(const int r) {
            const int index = indices(r);
            if (index < 0) return;
            int m = static_cast<int>(buf(r));
            if (r >= nrecv1) m = nextrarecv1 + static_cast<int>(buf(nextrarecv1 + r - nrecv1));
            for (int k = 0; k < na; ++k) a(index, k) = buf(m++);
            for (int k = 0; k < nb; ++k) b(index, k) = buf(m++);
            for (int k = 0; k < nc; ++k) c(index, k) = buf(m++);
          });
      modify_rows(k_a, k_b, k_c);
    }

    // atom sorting permutes the rows on the device (as fix neigh/history/kk)
    template <class Sorter> static void sort(Sorter &sorter, tdual_state &k_a, tdual_state &k_b,
                                             tdual_state &k_c)
    {
      for (tdual_state *k : {&k_a, &k_b, &k_c}) {
        k->sync_device();
        sorter.sort(LMPDeviceType(), k->view_device());
        k->modify_device();
      }
    }
  };
#endif

  // the flags that let LAMMPS move a Kokkos fix's per-atom arrays (`row` doubles per
  // atom) on the device; nothing for LAMMPS 29Sep2021, which cannot
  inline void enable_device_exchange(Fix *fix, int row)
  {
#if GRANSPH_KOKKOS_NEW_API
    fix->exchange_comm_device = 1;
    fix->sort_device = 1;
    if (fix->maxexchange < row + 1) fix->maxexchange = row + 1;    // offsets and rows
#else
    (void) fix;
    (void) row;
#endif
  }

}    // namespace GRANSPHCompat
}    // namespace LAMMPS_NS

// In the class of a Kokkos fix: the hooks that move its three per-atom DualViews of rows
// of doubles, a, b and c, with the atoms on the device (exchange and sort), which LAMMPS
// 2025+ does if the fix says it can (enable_device_exchange); 29Sep2021 always copies
// them through the host
#if GRANSPH_KOKKOS_NEW_API
#define GRANSPH_KOKKOS_FIX_DEVICE_EXCHANGE(a, b, c)                                            \
  int pack_exchange_kokkos(const int &nsend, DAT::tdual_double_2d_lr &k_buf,                   \
                           DAT::tdual_int_1d k_sendlist, DAT::tdual_int_1d k_copylist,         \
                           ExecutionSpace space) override                                      \
  {                                                                                            \
    return GRANSPHCompat::DeviceExchange<DeviceType>::pack(nsend, k_buf, k_sendlist,           \
                                                           k_copylist, space, a, b, c);        \
  }                                                                                            \
  void unpack_exchange_kokkos(DAT::tdual_double_2d_lr &k_buf, DAT::tdual_int_1d &k_indices,    \
                              int nrecv, int nrecv1, int nextrarecv1, ExecutionSpace) override \
  {                                                                                            \
    GRANSPHCompat::DeviceExchange<DeviceType>::unpack(k_buf, k_indices, nrecv, nrecv1,         \
                                                      nextrarecv1, a, b, c);                   \
  }                                                                                            \
  void sort_kokkos(Kokkos::BinSort<KokkosBase::KeyViewType, KokkosBase::BinOp> &sorter)        \
      override                                                                                 \
  {                                                                                            \
    GRANSPHCompat::DeviceExchange<DeviceType>::sort(sorter, a, b, c);                          \
  }
#else
#define GRANSPH_KOKKOS_FIX_DEVICE_EXCHANGE(a, b, c)
#endif

// In the class of a Kokkos fix (GRANSPH_KOKKOS_FIX_FORWARD_COMM) or pair style
// (GRANSPH_KOKKOS_PAIR_FORWARD_COMM), with typedef AT::... and a DeviceType: the
// forward-communication hooks of this LAMMPS version (their names and signatures changed
// after 2021: one send list per swap, the buffer type), forwarding to
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
#define GRANSPH_KOKKOS_PAIR_FORWARD_COMM GRANSPH_KOKKOS_FIX_FORWARD_COMM
#else
// 29Sep2021 names a pair's hooks and a fix's apart
#define GRANSPH_KOKKOS_FORWARD_COMM_AS(pack, unpack)                                            \
  int pack(int n, DAT::tdual_int_2d k_sendlist, int iswap, DAT::tdual_xfloat_1d &k_buf, int,  \
           int *) override                                                                     \
  {                                                                                            \
    return pack_forward_comm_device(n, {k_sendlist.template view<DeviceType>(), iswap}, k_buf); \
  }                                                                                            \
  void unpack(int n, int first, DAT::tdual_xfloat_1d &k_buf) override                         \
  {                                                                                            \
    unpack_forward_comm_device(n, first, k_buf);                                               \
  }
#define GRANSPH_KOKKOS_PAIR_FORWARD_COMM                                                        \
  GRANSPH_KOKKOS_FORWARD_COMM_AS(pack_forward_comm_kokkos, unpack_forward_comm_kokkos)
#define GRANSPH_KOKKOS_FIX_FORWARD_COMM                                                         \
  GRANSPH_KOKKOS_FORWARD_COMM_AS(pack_forward_comm_fix_kokkos, unpack_forward_comm_fix_kokkos)
#endif

#endif
