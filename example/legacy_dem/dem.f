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
      END
