! Plays Abaqus/Standard's part for user subroutine UINTER: reads call records, calls
! UINTER with the argument list of the Abaqus User Subroutines Reference (double
! precision reals, default integers, CHARACTER*80 names) and writes what it returns.
!
! Input (stream of float64): the number of calls, then per call
!   ndir, props(22), stress(3), statev(8), rdisp(3), drdisp(3), dtime      (41 values)
! Output (stream of float64) per call:
!   stress(3), statev(8), ddsddr(3,3) (its leading ndir x ndir block), pnewdt, lopenclose
program harness_uinter
  implicit none
  integer, parameter :: nprops = 22, nstatv = 8, npred = 1, mcrd = 3
  character(len=4096) :: path_in, path_out
  character(len=80) :: ciname, secname, mainname
  double precision :: header, rec(41), out(23)
  double precision :: stress(3), ddsddr(9), dviscous(9), dstructural(9), flux(2)
  double precision :: ddfddt(2, 2), ddsddt(3, 2), ddfddr(2, 3), statev(nstatv)
  double precision :: sed, sfd, spd, svd, scd, pnewdt, rdisp(3), drdisp(3)
  double precision :: temp(2), dtemp(2), predef(2, npred), dpred(2, npred), time(2), dtime
  double precision :: freqr, props(nprops), coords(mcrd), alocaldir(3, 3), drot(2, 2)
  double precision :: area, chrlngth
  integer :: node, ndir, kstep, kinc, kit, linper, lopenclose, lstate, lsdi, lprint
  integer :: ncalls, k, i, j, uin, uout
  external uinter

  call get_command_argument(1, path_in)
  call get_command_argument(2, path_out)
  open (newunit=uin, file=trim(path_in), access='stream', form='unformatted', status='old')
  open (newunit=uout, file=trim(path_out), access='stream', form='unformatted', &
        status='replace')
  read (uin) header
  ncalls = nint(header)
  ciname = 'FRICTIONLAB'
  secname = 'SLAVE'
  mainname = 'MASTER'
  temp = 0d0; dtemp = 0d0; predef = 0d0; dpred = 0d0; time = 0d0; freqr = 0d0
  coords = 0d0; alocaldir = 0d0; drot = 0d0; area = 1d0; chrlngth = 1d0
  do i = 1, 3
    alocaldir(i, i) = 1d0
  end do
  drot(1, 1) = 1d0; drot(2, 2) = 1d0
  node = 1; kstep = 1; kinc = 1; kit = 1; linper = 0; lprint = 0
  do k = 1, ncalls
    read (uin) rec
    ndir = nint(rec(1))
    props = rec(2:23)
    stress = rec(24:26)
    statev = rec(27:34)
    rdisp = rec(35:37)
    drdisp = rec(38:40)
    dtime = rec(41)
    ddsddr = 0d0; dviscous = 0d0; dstructural = 0d0; flux = 0d0; ddfddt = 0d0
    ddsddt = 0d0; ddfddr = 0d0; sed = 0d0; sfd = 0d0; spd = 0d0; svd = 0d0; scd = 0d0
    pnewdt = 1d0; lopenclose = -1; lstate = 0; lsdi = 0
    call uinter(stress, ddsddr, dviscous, dstructural, flux, ddfddt, &
                ddsddt, ddfddr, statev, sed, sfd, spd, svd, scd, pnewdt, rdisp, &
                drdisp, &
                temp, dtemp, predef, dpred, time, dtime, freqr, ciname, secname, &
                mainname, &
                props, coords, alocaldir, drot, area, chrlngth, node, ndir, nstatv, &
                npred, nprops, mcrd, kstep, kinc, kit, linper, lopenclose, lstate, &
                lsdi, lprint)
    out = 0d0
    out(1:3) = stress
    out(4:11) = statev
    do j = 1, ndir
      do i = 1, ndir
        out(11 + i + 3*(j - 1)) = ddsddr(i + ndir*(j - 1))
      end do
    end do
    out(21) = pnewdt
    out(22) = dble(lopenclose)
    out(23) = dble(lsdi)
    write (uout) out
  end do
  close (uin)
  close (uout)
end program harness_uinter
