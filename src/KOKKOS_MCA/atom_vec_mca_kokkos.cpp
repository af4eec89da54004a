// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

/* ----------------------------------------------------------------------
   Contributing authors: MCA package developers
------------------------------------------------------------------------- */

#include "atom_vec_mca_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_mca_impl.h"
#include "comm_kokkos.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "modify.h"

using namespace LAMMPS_NS;

namespace LAMMPS_NS {
template class AtomVecMCAStyle<AtomVecKokkos>;
}

// number of per-atom fields atom_style mca grows besides the common ones
// (molecule, bonds and specials, omega, torque, radius, rmass, quat and
// the ten mca_* fields); grow() below must grow each of them
static constexpr int MCA_NGROW = 21;

/* ---------------------------------------------------------------------- */

AtomVecMCAKokkos::AtomVecMCAKokkos(LAMMPS *lmp) :
    MCA_KK_ATOMVEC_BASE(lmp) AtomVecMCAStyle<AtomVecKokkos>(lmp)
{
  MCAKokkos::require_kokkos(lmp, "Atom style mca/kk");
  owns_arrays = 0;    // the DualViews below own the MCA fields
#ifndef MCA_HAVE_KK_AVEC_VIRTUAL
  commKK = (CommKokkos *) comm;    // AtomVecKokkos leaves it to the styles
  no_comm_vel_flag = 0;
  no_border_vel_flag = 1;
#endif
}

/* ---------------------------------------------------------------------- */

AtomVecMCAKokkos::~AtomVecMCAKokkos()
{
  memoryKK->destroy_kokkos(k_packing, packing);
  memoryKK->destroy_kokkos(k_given, given);
  memoryKK->destroy_kokkos(k_volume, volume);
  memoryKK->destroy_kokkos(k_inertia, inertia);
  memoryKK->destroy_kokkos(k_smean, smean);
  memoryKK->destroy_kokkos(k_stress, stress);
  memoryKK->destroy_kokkos(k_seq, seq);
  memoryKK->destroy_kokkos(k_eeq, eeq);
  memoryKK->destroy_kokkos(k_epsp, epsp);
  memoryKK->destroy_kokkos(k_damage, damage);
  memoryKK->destroy_kokkos(k_quat, quat);
#ifdef MCA_HAVE_ATOM_QUAT
  atom->quat = nullptr;    // was the host view of k_quat: Atom must not free it
#endif
}

/* ----------------------------------------------------------------------
   exchange and borders (and since 2023 sorting) through the host (see the
   header); set before CommKokkos::init() and AtomKokkos::init() copy it,
   at every init since the package command may have reset it.  The sync
   masks of the field lists get the bits of the MCA fields, which
   AtomVecKokkos does not know
------------------------------------------------------------------------- */

void AtomVecMCAKokkos::init()
{
  AtomVecMCAStyle<AtomVecKokkos>::init();
  if (ngrow != MCA_NGROW)
    error->all(FLERR,
               "Atom style mca/kk: atom_style mca grows {} fields, mca/kk {}: "
               "the Kokkos style is out of date",
               ngrow, MCA_NGROW);
  MCAKokkos::use_host_exchange(lmp->kokkos);
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
  set_atom_masks();
  const uint64_t mca_fields = MCA_GEOMETRY_MASK | MCA_STATE_MASK | MCA_QUAT_MASK;
  datamask_grow |= mca_fields;
  datamask_border |= mca_fields;
  datamask_border_vel |= mca_fields;
  datamask_exchange |= mca_fields;
#endif
}

/* ----------------------------------------------------------------------
   grow all per-atom arrays by DELTA (n = 0) or to n; every field of the
   field lists of atom_style mca is a DualView whose host view the
   pointers of Atom and MCAAtomFields alias
------------------------------------------------------------------------- */

void AtomVecMCAKokkos::grow(int n)
{
  const bigint step = MAX(LMP_KOKKOS_AV_DELTA, (bigint) (nmax * 0.01));
  if (n == 0)
    nmax += step;
  else
    nmax = n;
  atom->nmax = nmax;
  if (nmax < 0 || nmax > MAXSMALLINT) error->one(FLERR, "Per-processor system is too big");

  atomKK->sync(Device, ALL_MASK);
  atomKK->modified(Device, ALL_MASK);

  memoryKK->grow_kokkos(atomKK->k_tag, atomKK->tag, nmax, "atom:tag");
  memoryKK->grow_kokkos(atomKK->k_type, atomKK->type, nmax, "atom:type");
  memoryKK->grow_kokkos(atomKK->k_mask, atomKK->mask, nmax, "atom:mask");
  memoryKK->grow_kokkos(atomKK->k_image, atomKK->image, nmax, "atom:image");
  memoryKK->grow_kokkos(atomKK->k_x, atomKK->x, nmax, "atom:x");
  memoryKK->grow_kokkos(atomKK->k_v, atomKK->v, nmax, "atom:v");
  memoryKK->grow_kokkos(atomKK->k_f, atomKK->f, nmax, "atom:f");

  memoryKK->grow_kokkos(atomKK->k_molecule, atomKK->molecule, nmax, "atom:molecule");
  memoryKK->grow_kokkos(atomKK->k_num_bond, atomKK->num_bond, nmax, "atom:num_bond");
  memoryKK->grow_kokkos(atomKK->k_bond_type, atomKK->bond_type, nmax, atomKK->bond_per_atom,
                        "atom:bond_type");
  memoryKK->grow_kokkos(atomKK->k_bond_atom, atomKK->bond_atom, nmax, atomKK->bond_per_atom,
                        "atom:bond_atom");
  memoryKK->grow_kokkos(atomKK->k_nspecial, atomKK->nspecial, nmax, 3, "atom:nspecial");
  memoryKK->grow_kokkos(atomKK->k_special, atomKK->special, nmax, atomKK->maxspecial,
                        "atom:special");
  memoryKK->grow_kokkos(atomKK->k_omega, atomKK->omega, nmax, "atom:omega");
  memoryKK->grow_kokkos(atomKK->k_torque, atomKK->torque, nmax, "atom:torque");
  memoryKK->grow_kokkos(atomKK->k_radius, atomKK->radius, nmax, "atom:radius");
  memoryKK->grow_kokkos(atomKK->k_rmass, atomKK->rmass, nmax, "atom:rmass");

  memoryKK->grow_kokkos(k_quat, quat, nmax, 4, "atom:quat");
#ifdef MCA_HAVE_ATOM_QUAT
  atom->quat = quat;    // the field lists reach the orientation through Atom
#endif
  memoryKK->grow_kokkos(k_packing, packing, nmax, "atom:mca_packing");
  memoryKK->grow_kokkos(k_given, given, nmax, "atom:mca_given");
  memoryKK->grow_kokkos(k_volume, volume, nmax, "atom:mca_volume");
  memoryKK->grow_kokkos(k_inertia, inertia, nmax, "atom:mca_inertia");
  memoryKK->grow_kokkos(k_smean, smean, nmax, "atom:mca_smean");
  memoryKK->grow_kokkos(k_stress, stress, nmax, NSTRESS, "atom:mca_stress");
  memoryKK->grow_kokkos(k_seq, seq, nmax, "atom:mca_seq");
  memoryKK->grow_kokkos(k_eeq, eeq, nmax, "atom:mca_eeq");
  memoryKK->grow_kokkos(k_epsp, epsp, nmax, "atom:mca_epsp");
  memoryKK->grow_kokkos(k_damage, damage, nmax, "atom:mca_damage");

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->grow_arrays(nmax);

  grow_pointers();
  atomKK->sync(Host, ALL_MASK);
}

/* ---------------------------------------------------------------------- */

void AtomVecMCAKokkos::grow_pointers()
{
  AtomVecMCAStyle<AtomVecKokkos>::grow_pointers();
  // the generic AtomVec methods work through these
  tag = atomKK->tag;
  type = atomKK->type;
  mask = atomKK->mask;
  image = atomKK->image;
  x = atomKK->x;
  v = atomKK->v;
  f = atomKK->f;
#ifndef MCA_HAVE_KK_AVEC_VIRTUAL
  // the host packing of the 2021 AtomVecKokkos reads these
  h_x = atomKK->k_x.view_host();
  h_v = atomKK->k_v.view_host();
  h_f = atomKK->k_f.view_host();
#endif
}

/* ----------------------------------------------------------------------
   apply a DualView operation to every view selected by mask
------------------------------------------------------------------------- */

template <class Apply> void AtomVecMCAKokkos::for_each_view(MCAKokkos::mask_t mask, Apply apply)
{
  if (mask & X_MASK) apply(atomKK->k_x);
  if (mask & V_MASK) apply(atomKK->k_v);
  if (mask & F_MASK) apply(atomKK->k_f);
  if (mask & TAG_MASK) apply(atomKK->k_tag);
  if (mask & TYPE_MASK) apply(atomKK->k_type);
  if (mask & MASK_MASK) apply(atomKK->k_mask);
  if (mask & IMAGE_MASK) apply(atomKK->k_image);
  if (mask & MOLECULE_MASK) apply(atomKK->k_molecule);
  if (mask & BOND_MASK) {
    apply(atomKK->k_num_bond);
    apply(atomKK->k_bond_type);
    apply(atomKK->k_bond_atom);
  }
  if (mask & SPECIAL_MASK) {
    apply(atomKK->k_nspecial);
    apply(atomKK->k_special);
  }
  if (mask & RADIUS_MASK) apply(atomKK->k_radius);
  if (mask & RMASS_MASK) apply(atomKK->k_rmass);
  if (mask & OMEGA_MASK) apply(atomKK->k_omega);
  if (mask & TORQUE_MASK) apply(atomKK->k_torque);
  if (mask & MCA_GEOMETRY_MASK) {
    apply(k_packing);
    apply(k_given);
    apply(k_volume);
    apply(k_inertia);
  }
  if (mask & MCA_STATE_MASK) {
    apply(k_smean);
    apply(k_stress);
    apply(k_seq);
    apply(k_eeq);
    apply(k_epsp);
    apply(k_damage);
  }
  if (mask & MCA_QUAT_MASK) apply(k_quat);
}

void AtomVecMCAKokkos::sync(ExecutionSpace space, MCAKokkos::mask_t mask)
{
  for_each_view(mask, [space](auto &view) {
    MCAKokkos::sync_view(view, space);
  });
}

void AtomVecMCAKokkos::modified(ExecutionSpace space, MCAKokkos::mask_t mask)
{
  for_each_view(mask, [space](auto &view) {
    MCAKokkos::modify_view(view, space);
  });
}

void AtomVecMCAKokkos::sync_host()
{
  atomKK->sync(Host, ALL_MASK);
}

void AtomVecMCAKokkos::modified_host()
{
  atomKK->modified(Host, ALL_MASK);
}

void AtomVecMCAKokkos::orientation_to_host()
{
  atomKK->sync(Host, MCA_QUAT_MASK);
}

void AtomVecMCAKokkos::orientation_changed_on_host()
{
  atomKK->modified(Host, MCA_QUAT_MASK);
}

/* ----------------------------------------------------------------------
   reaching a device path that init() switched off is an internal error
------------------------------------------------------------------------- */

void AtomVecMCAKokkos::host_only(const char *what)
{
  error->one(FLERR,
             "Atom style mca/kk {} on the host only (the link table of its automata "
             "lives in a fix), but the device path was called: please report this",
             what);
}

#ifdef MCA_HAVE_KK_AVEC_VIRTUAL

/* ----------------------------------------------------------------------
   LAMMPS 2023 and later: copies are not overlapped with computation, a
   plain sync is correct; atoms are sorted on the host (init())
------------------------------------------------------------------------- */

void AtomVecMCAKokkos::sync_pinned(ExecutionSpace space, uint64_t mask, int)
{
  sync(space, mask);
}

void AtomVecMCAKokkos::sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &)
{
  host_only("sorts atoms");
}

#else

/* ----------------------------------------------------------------------
   LAMMPS 2021
------------------------------------------------------------------------- */

// copies are not overlapped with computation: a plain sync is correct and
// the MCA styles do not request overlapping transfers
void AtomVecMCAKokkos::sync_overlapping_device(ExecutionSpace space, unsigned int mask)
{
  sync(space, mask);
}

/* ----------------------------------------------------------------------
   host communication with the generic field lists of atom_style mca
------------------------------------------------------------------------- */

int AtomVecMCAKokkos::pack_comm_vel(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  atomKK->sync(Host, X_MASK | V_MASK | OMEGA_MASK | MASK_MASK);
  return AtomVec::pack_comm_vel(n, list, buf, pbc_flag, pbc);
}

void AtomVecMCAKokkos::unpack_comm_vel(int n, int first, double *buf)
{
  atomKK->sync(Host, X_MASK | V_MASK | OMEGA_MASK);
  AtomVec::unpack_comm_vel(n, first, buf);
  atomKK->modified(Host, X_MASK | V_MASK | OMEGA_MASK);
}

int AtomVecMCAKokkos::pack_reverse(int n, int first, double *buf)
{
  atomKK->sync(Host, F_MASK | TORQUE_MASK);
  return AtomVec::pack_reverse(n, first, buf);
}

void AtomVecMCAKokkos::unpack_reverse(int n, int *list, double *buf)
{
  atomKK->sync(Host, F_MASK | TORQUE_MASK);
  AtomVec::unpack_reverse(n, list, buf);
  atomKK->modified(Host, F_MASK | TORQUE_MASK);
}

void AtomVecMCAKokkos::data_vel(int m, char **values)
{
  atomKK->sync(Host, V_MASK | OMEGA_MASK);
  AtomVec::data_vel(m, values);
  atomKK->modified(Host, V_MASK | OMEGA_MASK);
}

void AtomVecMCAKokkos::pack_vel(double **buf)
{
  atomKK->sync(Host, V_MASK | OMEGA_MASK | TAG_MASK);
  AtomVec::pack_vel(buf);
}

void AtomVecMCAKokkos::write_vel(FILE *fp, int n, double **buf)
{
  AtomVec::write_vel(fp, n, buf);
}

/* ----------------------------------------------------------------------
   ghost positions, velocities and spins on the device (comm_modify vel yes,
   which pair mca requires); the shifts are those of AtomVec::pack_comm_vel
------------------------------------------------------------------------- */

namespace {
template <class DeviceType> struct MCAPackCommVel {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v, omega;
  typename AT::t_int_1d_randomread mask;
  typename AT::t_xfloat_2d_um buf;
  typename AT::t_int_2d_const list;
  int iswap, deform_groupbit;
  double dx[3], dv[3];

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    const int j = list(iswap, i);
    const bool remap_v = deform_groupbit && (mask(j) & deform_groupbit);
    for (int k = 0; k < 3; k++) {
      buf(i, k) = x(j, k) + dx[k];
      buf(i, 3 + k) = remap_v ? v(j, k) + dv[k] : v(j, k);
      buf(i, 6 + k) = omega(j, k);
    }
  }
};

template <class DeviceType> struct MCAUnpackCommVel {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  typename AT::t_v_array v, omega;
  typename AT::t_xfloat_2d_um buf;
  int first;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    for (int k = 0; k < 3; k++) {
      x(first + i, k) = buf(i, k);
      v(first + i, k) = buf(i, 3 + k);
      omega(first + i, k) = buf(i, 6 + k);
    }
  }
};

constexpr int COMM_VEL_SIZE = 9;
}    // namespace

template <class DeviceType>
int AtomVecMCAKokkos::pack_comm_vel_on(int n, const DAT::tdual_int_2d &list, int iswap,
                                       const DAT::tdual_xfloat_2d &buf, int pbc_flag,
                                       const int pbc[])
{
  const ExecutionSpace space = MCAKokkos::space_of<DeviceType>();
  atomKK->sync(space, X_MASK | V_MASK | OMEGA_MASK | MASK_MASK);

  MCAPackCommVel<DeviceType> pack;
  pack.x = atomKK->k_x.view<DeviceType>();
  pack.v = atomKK->k_v.view<DeviceType>();
  pack.omega = atomKK->k_omega.view<DeviceType>();
  pack.mask = atomKK->k_mask.view<DeviceType>();
  pack.list = list.view<DeviceType>();
  pack.iswap = iswap;
  auto dbuf = buf.view<DeviceType>();
  const int maxsend = (dbuf.extent(0) * dbuf.extent(1)) / COMM_VEL_SIZE;
  pack.buf = typename ArrayTypes<DeviceType>::t_xfloat_2d_um(dbuf.data(), maxsend, COMM_VEL_SIZE);
  pack.deform_groupbit = 0;
  for (int k = 0; k < 3; k++) pack.dx[k] = pack.dv[k] = 0.0;
  if (pbc_flag) {
    if (domain->triclinic == 0) {
      pack.dx[0] = pbc[0] * domain->xprd;
      pack.dx[1] = pbc[1] * domain->yprd;
      pack.dx[2] = pbc[2] * domain->zprd;
    } else {
      pack.dx[0] = pbc[0] * domain->xprd + pbc[5] * domain->xy + pbc[4] * domain->xz;
      pack.dx[1] = pbc[1] * domain->yprd + pbc[3] * domain->yz;
      pack.dx[2] = pbc[2] * domain->zprd;
    }
    if (deform_vremap) {
      pack.deform_groupbit = deform_groupbit;
      pack.dv[0] = pbc[0] * h_rate[0] + pbc[5] * h_rate[5] + pbc[4] * h_rate[4];
      pack.dv[1] = pbc[1] * h_rate[1] + pbc[3] * h_rate[3];
      pack.dv[2] = pbc[2] * h_rate[2];
    }
  }
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, n), pack);
  return n * COMM_VEL_SIZE;
}

template <class DeviceType>
void AtomVecMCAKokkos::unpack_comm_vel_on(int n, int first, const DAT::tdual_xfloat_2d &buf)
{
  const ExecutionSpace space = MCAKokkos::space_of<DeviceType>();
  atomKK->sync(space, X_MASK | V_MASK | OMEGA_MASK);

  MCAUnpackCommVel<DeviceType> unpack;
  unpack.x = atomKK->k_x.view<DeviceType>();
  unpack.v = atomKK->k_v.view<DeviceType>();
  unpack.omega = atomKK->k_omega.view<DeviceType>();
  auto dbuf = buf.view<DeviceType>();
  const int maxrecv = (dbuf.extent(0) * dbuf.extent(1)) / COMM_VEL_SIZE;
  unpack.buf = typename ArrayTypes<DeviceType>::t_xfloat_2d_um(dbuf.data(), maxrecv, COMM_VEL_SIZE);
  unpack.first = first;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, n), unpack);
  atomKK->modified(space, X_MASK | V_MASK | OMEGA_MASK);
}

int AtomVecMCAKokkos::pack_comm_vel_kokkos(const int &n, const DAT::tdual_int_2d &list,
                                           const int &iswap, const DAT::tdual_xfloat_2d &buf,
                                           const int &pbc_flag, const int pbc[])
{
  if (commKK->forward_comm_on_host)
    return pack_comm_vel_on<LMPHostType>(n, list, iswap, buf, pbc_flag, pbc);
  return pack_comm_vel_on<LMPDeviceType>(n, list, iswap, buf, pbc_flag, pbc);
}

void AtomVecMCAKokkos::unpack_comm_vel_kokkos(const int &n, const int &first,
                                              const DAT::tdual_xfloat_2d &buf)
{
  if (commKK->forward_comm_on_host)
    unpack_comm_vel_on<LMPHostType>(n, first, buf);
  else
    unpack_comm_vel_on<LMPDeviceType>(n, first, buf);
}

/* ----------------------------------------------------------------------
   borders and exchange run on the host for this style (init() selects
   the classic communication); reaching these is an internal error
------------------------------------------------------------------------- */

int AtomVecMCAKokkos::pack_border_kokkos(int, DAT::tdual_int_2d, DAT::tdual_xfloat_2d, int, int,
                                         int *, ExecutionSpace)
{
  host_only("sends ghost atoms");
  return 0;
}

void AtomVecMCAKokkos::unpack_border_kokkos(const int &, const int &, const DAT::tdual_xfloat_2d &,
                                            ExecutionSpace)
{
  host_only("sends ghost atoms");
}

int AtomVecMCAKokkos::pack_exchange_kokkos(const int &, DAT::tdual_xfloat_2d &, DAT::tdual_int_1d,
                                           DAT::tdual_int_1d, ExecutionSpace, int, X_FLOAT, X_FLOAT)
{
  host_only("sends migrating atoms");
  return 0;
}

int AtomVecMCAKokkos::unpack_exchange_kokkos(DAT::tdual_xfloat_2d &, int, int, int, X_FLOAT,
                                             X_FLOAT, ExecutionSpace)
{
  host_only("sends migrating atoms");
  return 0;
}

#endif
