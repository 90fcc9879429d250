/* mech/rigid.h — every public header of the rigid domain in one include:
 * rigid bodies (notes chapter 2): inertia tensors of parts and meshes,
 * Euler's equations and the torque-free body's closed form, the heavy top,
 * stability of spin, the chapter's closed-form problems.
 * One header per concept lives in mech/rigid/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_RIGID_ALL_H
#define MECH_RIGID_ALL_H

#include "mech/rigid/inertia.h"
#include "mech/rigid/mesh.h"
#include "mech/rigid/rigid_closed_form.h"
#include "mech/rigid/rigid_problems.h"
#include "mech/rigid/rigid_rotation.h"
#include "mech/rigid/stability.h"
#include "mech/rigid/sym_tensor.h"
#include "mech/rigid/top.h"

#endif
