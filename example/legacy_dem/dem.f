C     dem.f: a particle dropped on a wall under gravity, in the style of
C     a legacy fixed-form DEM code.  At the onset of every contact the
C     stiffness K and damping D come from HERTZDAMP_INVERT (target
C     restitution ETARG, contact time TC = NSTEP*DT, mass AM, impact
C     speed UIN of that contact); the contact force is
C         F = K*Z**1.5 + D*ZDOT      (Z overlap, ZDOT = -V)
C     and the contact ends when the overlap returns to zero.  Time
C     stepping: velocity Verlet (damping on the half-step velocity).
C     Per contact it prints UIN, K, D and the achieved ratio of
C     rebound to impact speed, plus E and TC that HERTZDAMP_FORWARD
C     predicts for K, D (gravity and time stepping are not in it).
C
C     Then (subroutine EULER) MFiX's explicit Euler scheme, at many
C     onset phases, with the per-pair API: HERTZDAMP_PAIR_INIT once per
C     material pair for the host scheme (IHOST = 2, mfix-euler, exact
C     for this scheme at NSTEP steps per contact; IHOST = 0 the
C     continuous model) and HERTZDAMP_PAIR_KD at every contact onset.
C     Last (subroutine EULERP) the same loop with per-contact constants:
C     HERTZDAMP_PAIR_INIT_PHASE once, and at every onset the phase
C     PHI = HERTZDAMP_ONSET_PHASE(first overlap, speed, DT) and
C     HERTZDAMP_PAIR_KD_PHASE: every single contact exact (issue 32).
C
C     Build against an installed prefix:  make PREFIX=/path/to/prefix
C     INCLUDE 'hertzdamp.fi' (from PREFIX/include) declares the library
C     routines: an argument of the wrong type or kind is then a compile
C     error, not garbage.
      PROGRAM DEM
      IMPLICIT NONE
      INCLUDE 'hertzdamp.fi'
      DOUBLE PRECISION AM, G, DT, ETARG, H0, X, V, VH, A, F, Z, ZDOT
      DOUBLE PRECISION AK, D, UIN, TC, EPRED, TCPRED, T, TON
      INTEGER NSTEP, NCONT, MAXCON, IERR, ISTEP, IEND
      LOGICAL INCONT
      CHARACTER*100 TEXT
C     mass [kg], gravity [m/s2], time step [s], target restitution
      PARAMETER (AM = 1.0D-3, G = 9.81D0, DT = 1.0D-5, ETARG = 0.8D0)
C     steps per contact, drop height [m], contacts to resolve
      PARAMETER (NSTEP = 10, H0 = 0.1D0, MAXCON = 5)
      PARAMETER (IEND = 0)
C
      TC = NSTEP*DT
      X = H0
      V = 0.0D0
      T = 0.0D0
      TON = 0.0D0
      AK = 0.0D0
      D = 0.0D0
      UIN = 0.0D0
      NCONT = 0
      INCONT = .FALSE.
      A = -G
      WRITE (*,'(A)') '# legacy DEM: contact, u_in [m/s], k [N/m^1.5], '
     &   // 'd [kg/s], achieved v_out/u_in, steps in contact, '
     &   // 'predicted e, predicted T_c [s]'
      DO 100 ISTEP = 1, 10000000
C        velocity Verlet: half kick, drift
         VH = V + 0.5D0*DT*A
         X = X + DT*VH
         T = T + DT
C        contact onset: parameters for this contact
         IF (.NOT. INCONT .AND. X .LT. 0.0D0) THEN
            INCONT = .TRUE.
            NCONT = NCONT + 1
            TON = T
            UIN = -VH
            CALL HERTZDAMP_INVERT(ETARG, TC, AM, UIN, IEND, AK, D, IERR)
            IF (IERR .NE. 0) THEN
               CALL HERTZDAMP_MESSAGE(IERR, TEXT)
               WRITE (*,'(A,A)') 'hertzdamp_invert failed: ', TEXT
               STOP 1
            END IF
            CALL HERTZDAMP_FORWARD(AK, D, AM, UIN, IEND, EPRED, TCPRED,
     &                             IERR)
            IF (IERR .NE. 0) THEN
               CALL HERTZDAMP_MESSAGE(IERR, TEXT)
               WRITE (*,'(A,A)') 'hertzdamp_forward failed: ', TEXT
               STOP 1
            END IF
         END IF
C        force from the new position and the half-step velocity
         F = -AM*G
         IF (X .LT. 0.0D0) THEN
            Z = -X
            ZDOT = -VH
            F = F + AK*Z**1.5D0 + D*ZDOT
         END IF
         A = F/AM
         V = VH + 0.5D0*DT*A
C        contact end: the overlap has returned to zero
         IF (INCONT .AND. X .GE. 0.0D0) THEN
            INCONT = .FALSE.
            WRITE (*,'(A,I3,1P,3E25.16E3,0P,F12.8,I6,1P,2E25.16E3)')
     &         'contact', NCONT, UIN, AK, D, V/UIN,
     &         NINT((T - TON)/DT), EPRED, TCPRED
            IF (NCONT .GE. MAXCON) GO TO 200
         END IF
  100 CONTINUE
  200 CONTINUE
      CALL EULER(2)
      CALL EULER(0)
      CALL EULERP(0.2D0, 10)
      CALL EULERP(0.5D0, 10)
      CALL EULERP(0.9D0, 10)
      CALL EULERP(0.2D0, 20)
      CALL EULERP(0.5D0, 20)
      CALL EULERP(0.9D0, 20)
      END
C
C     EULER: head-on sphere-wall collisions (no gravity) integrated as
C     MFiX's DES_INTG_METHOD = 'EULER' does (model/des/cfnewvalues.f):
C         V = V + DT*A;   X = X + DT*V;   A from the new X and V,
C     at NPH onset phases: sphere J starts (2 + (J-1/2)/NPH)*U*DT above
C     the touch, so its first overlap is PHI*U*DT, PHI = 1-(J-1/2)/NPH
C     (one contact in each of NPH equal cells of the phase).  K and D of
C     each contact come from HERTZDAMP_PAIR_KD with the constants that
C     HERTZDAMP_PAIR_INIT gave once for the pair (host IHOST, NSTEP
C     steps per contact).  The contact lasts while the overlap is > 0;
C     its T_c runs from the touch to the overlap zero (both interpolated
C     linearly in the overlap), its e is the speed after it over U.
C     Prints the mean e/ETARG - 1 and T_c/(NSTEP*DT) - 1 over the
C     phases, and the variation of e/ETARG and T_c/TC over them divided
C     by NPH; the stratified sampling error of the means is below it.
      SUBROUTINE EULER(IHOST)
      IMPLICIT NONE
      INCLUDE 'hertzdamp.fi'
      INTEGER IHOST
      DOUBLE PRECISION AM, DT, ETARG, U, TC, X, XOLD, V, A
      REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)
      DOUBLE PRECISION AK, D, UIN, T, TON, SE, ST, VE, VT, E1, T1
      DOUBLE PRECISION EPREV, TPREV
      INTEGER NSTEP, NPH, J, ISTEP, IERR, NDONE
      LOGICAL INCONT
      CHARACTER*100 TEXT
C     mass [kg], time step [s], target e, impact speed [m/s]
      PARAMETER (AM = 1.0D-3, DT = 1.0D-5, ETARG = 0.5D0, U = 1.0D0)
C     steps per contact, onset phases
      PARAMETER (NSTEP = 10, NPH = 1000)
      TC = NSTEP*DT
      CALL HERTZDAMP_PAIR_INIT(ETARG, 0, 0, IHOST, DBLE(NSTEP), PAIR,
     &                         IERR)
      IF (IERR .NE. 0) THEN
         CALL HERTZDAMP_MESSAGE(IERR, TEXT)
         WRITE (*,'(A,A)') 'hertzdamp_pair_init failed: ', TEXT
         STOP 1
      END IF
      SE = 0.0D0
      ST = 0.0D0
      VE = 0.0D0
      VT = 0.0D0
      EPREV = 0.0D0
      TPREV = 0.0D0
      NDONE = 0
      AK = 0.0D0
      D = 0.0D0
      UIN = 0.0D0
      TON = 0.0D0
      DO 300 J = 1, NPH
         X = (2.0D0 + (J - 0.5D0)/NPH)*U*DT
         V = -U
         A = 0.0D0
         INCONT = .FALSE.
         DO 250 ISTEP = 1, 1000
            T = ISTEP*DT
            V = V + DT*A
            XOLD = X
            X = X + DT*V
            A = 0.0D0
            IF (X .LT. 0.0D0) THEN
               IF (.NOT. INCONT) THEN
C                 onset: the touch inside this step, k and d
                  INCONT = .TRUE.
                  TON = T - DT + DT*XOLD/(XOLD - X)
                  UIN = -V
                  CALL HERTZDAMP_PAIR_KD(PAIR, TC, AM, UIN, 0.0D0, AK,
     &                                   D, IERR)
                  IF (IERR .NE. 0) THEN
                     CALL HERTZDAMP_MESSAGE(IERR, TEXT)
                     WRITE (*,'(2A)') 'hertzdamp_pair_kd failed: ', TEXT
                     STOP 1
                  END IF
               END IF
               A = (AK*(-X)**1.5D0 - D*V)/AM
            ELSE IF (INCONT) THEN
C              the overlap is gone: no force from here on
               E1 = V/UIN/ETARG
               T1 = (T - DT + DT*XOLD/(XOLD - X) - TON)/TC
               SE = SE + E1
               ST = ST + T1
               IF (J .GT. 1) THEN
                  VE = VE + ABS(E1 - EPREV)
                  VT = VT + ABS(T1 - TPREV)
               END IF
               EPREV = E1
               TPREV = T1
               NDONE = NDONE + 1
               GO TO 300
            END IF
  250    CONTINUE
  300 CONTINUE
      WRITE (*,'(A,I2,A,I5,A,I3,A,1P,4E12.4E2)') 'euler ihost',IHOST,
     &   ' phases', NDONE, ' steps', NSTEP,
     &   ' e_err tc_err e_var/n tc_var/n', SE/NDONE - 1.0D0,
     &   ST/NDONE - 1.0D0, VE/NDONE, VT/NDONE
      END SUBROUTINE EULER
C
C     EULERP: the loop of EULER (mfix-euler, linear law, overlap end)
C     with the constants of each contact's own onset phase: at the
C     onset, PHI from the first overlap -X, the speed UIN and DT
C     (HERTZDAMP_ONSET_PHASE), then K, D from HERTZDAMP_PAIR_KD_PHASE.
C     Prints the largest |e/ETARG - 1| and |T_c/TC - 1| of a single
C     contact over the NPH phases.
      SUBROUTINE EULERP(ETARG, NSTEP)
      IMPLICIT NONE
      INCLUDE 'hertzdamp.fi'
      REAL(8) ETARG
      INTEGER NSTEP
      DOUBLE PRECISION AM, DT, U, TC, X, XOLD, V, A, PHI
      REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)
      DOUBLE PRECISION AK, D, UIN, T, TON, E1, T1, EMAX, TMAX
      INTEGER NPH, J, ISTEP, IERR, NDONE
      LOGICAL INCONT
      CHARACTER*100 TEXT
      PARAMETER (AM = 1.0D-3, DT = 1.0D-5, U = 1.0D0, NPH = 1000)
      TC = NSTEP*DT
      CALL HERTZDAMP_PAIR_INIT_PHASE(ETARG, 0, 0, 2, DBLE(NSTEP),
     &                               PAIR, IERR)
      IF (IERR .NE. 0) THEN
         CALL HERTZDAMP_MESSAGE(IERR, TEXT)
         WRITE (*,'(A,A)') 'hertzdamp_pair_init_phase failed: ', TEXT
         STOP 1
      END IF
      EMAX = 0.0D0
      TMAX = 0.0D0
      NDONE = 0
      AK = 0.0D0
      D = 0.0D0
      UIN = 0.0D0
      TON = 0.0D0
      DO 400 J = 1, NPH
         X = (2.0D0 + (J - 0.5D0)/NPH)*U*DT
         V = -U
         A = 0.0D0
         INCONT = .FALSE.
         DO 350 ISTEP = 1, 1000
            T = ISTEP*DT
            V = V + DT*A
            XOLD = X
            X = X + DT*V
            A = 0.0D0
            IF (X .LT. 0.0D0) THEN
               IF (.NOT. INCONT) THEN
C                 onset: what the host knows here is the overlap -X,
C                 the speed and DT
                  INCONT = .TRUE.
                  TON = T - DT + DT*XOLD/(XOLD - X)
                  UIN = -V
                  CALL HERTZDAMP_ONSET_PHASE(-X, UIN, DT, PHI, IERR)
                  IF (IERR .EQ. 0) CALL HERTZDAMP_PAIR_KD_PHASE(PAIR,
     &               TC, AM, UIN, 0.0D0, PHI, AK, D, IERR)
                  IF (IERR .NE. 0) THEN
                     CALL HERTZDAMP_MESSAGE(IERR, TEXT)
                     WRITE (*,'(2A)') 'phase k, d failed: ', TEXT
                     STOP 1
                  END IF
               END IF
               A = (AK*(-X)**1.5D0 - D*V)/AM
            ELSE IF (INCONT) THEN
               E1 = V/UIN/ETARG
               T1 = (T - DT + DT*XOLD/(XOLD - X) - TON)/TC
               EMAX = MAX(EMAX, ABS(E1 - 1.0D0))
               TMAX = MAX(TMAX, ABS(T1 - 1.0D0))
               NDONE = NDONE + 1
               GO TO 400
            END IF
  350    CONTINUE
  400 CONTINUE
      WRITE (*,'(A,F5.2,A,I5,A,I3,A,1P,2E12.4E2)') 'euler-phase e',
     &   ETARG, ' phases', NDONE, ' steps', NSTEP,
     &   ' max_e_err max_tc_err', EMAX, TMAX
      END SUBROUTINE EULERP
