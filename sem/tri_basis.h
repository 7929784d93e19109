/* semquad sem/ — orthonormal (Dubiner) basis on the reference triangle.
 *
 * Modes (p,q), p+q <= P, numbered m = sem_tri_node_index(P,p,q) (same
 * numbering as the lattice).  Orthonormal in L2(T) on the reference triangle
 * T of tri_mesh.h (area 1/2). */
#ifndef SEM_TRI_BASIS_H
#define SEM_TRI_BASIS_H

#include "sq_status.h"

/* Values (phi) and reference derivatives (dr, ds) of all
 * (P+1)(P+2)/2 modes at (r,s); any output array may be NULL. */
void sem_tri_dubiner(int P, double r, double s, double *phi, double *dr, double *ds);

#endif
