!> Links pound's library from an install tree: a band matrix product and the version.
program pound_consumer
   use pound_kinds, only: dp
   use pound_band, only: band_symv
   use pound_version, only: program_version
   implicit none
   real(dp) :: ab(2, 3), y(3)

   ! Tridiagonal [2 -1 0; -1 2 -1; 0 -1 2] times (1, 1, 1) = (1, 0, 1).
   ab(1, :) = [0.0_dp, -1.0_dp, -1.0_dp]
   ab(2, :) = 2.0_dp
   call band_symv(ab, [1.0_dp, 1.0_dp, 1.0_dp], y)
   write (*, '(a,3f5.1)') 'pound '//program_version//' band_symv:', y
end program pound_consumer
