! Dump a DEM code's NBS y-lists for `nbscope verify` (Munjiza, ch. 3, NBS: the heads of the rows'
! y-lists and the next array Y(N)). Copy module nbs_arrays_json into your code and call
! write_nbs_ylists right after the y-lists are built, before the x-lists are.
!
! The JSON is the schema `nbscope dump --algorithm nbs` writes, with the book's numbering:
! "base": 1 says every element (row k of the elements CSV is element k + 1) and every row is
! counted from 1; -1 is an empty list or the end of one. Row iy spans [y0 + (iy-1)*d, y0 + iy*d).
!
!   gfortran -Wall -Wextra -std=f2008 write_arrays.F90 -o write_arrays_f && ./write_arrays_f > ylists.json
!   nbscope verify --input nine.csv --arrays ylists.json --algorithm nbs \
!                  --cell-size 1 --origin 0,0 --cells 10,10
!
! Add -DPLANT_BUG (the .F90 suffix runs the preprocessor) for the y-lists of a code with one bug.
module nbs_arrays_json
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none
  private
  public :: write_nbs_ylists

contains

  ! y_heads(iy): the first element of row iy's y-list; y_next(k): the element after k in its list.
  ! nx only completes the grid. g0 writes each real with enough digits to read back exactly
  ! (gfortran's form, e.g. 1.0000000000000000, is valid JSON).
  subroutine write_nbs_ylists(unit, nx, d, x0, y0, y_heads, y_next)
    integer, intent(in) :: unit, nx
    real(real64), intent(in) :: d, x0, y0
    integer, intent(in) :: y_heads(:), y_next(:)

    write (unit, '(a)') '{', '  "algorithm": "nbs",', '  "dim": 2,', '  "base": 1,'
    write (unit, '(a, i0, a)') '  "elements": ', size(y_next), ','
    write (unit, '(a, g0, a)') '  "cell_size": ', d, ','
    write (unit, '(a, g0, a, g0, a)') '  "origin": [', x0, ', ', y0, '],'
    write (unit, '(a, i0, a)') '  "nx": ', nx, ','
    write (unit, '(a, i0, a)') '  "ny": ', size(y_heads), ','
    call write_ints(unit, 'y_heads', y_heads, ',')
    call write_ints(unit, 'y_next', y_next, '')
    write (unit, '(a)') '}'
  end subroutine write_nbs_ylists

  ! One line: "key": [a(1), a(2), ...] then tail; ':' stops the list after its last item.
  subroutine write_ints(unit, key, a, tail)
    integer, intent(in) :: unit, a(:)
    character(*), intent(in) :: key, tail

    write (unit, '(3a, *(i0, :, ", "))', advance='no') '  "', key, '": [', a
    write (unit, '(2a)') ']', tail
  end subroutine write_ints

end module nbs_arrays_json

! The example: the nine elements of the book's Fig. 3.15 (assets/examples/nine.csv).
program write_arrays
  use, intrinsic :: iso_fortran_env, only: real64, output_unit
  use nbs_arrays_json, only: write_nbs_ylists
  implicit none
  integer, parameter :: dp = real64, n = 9, nx = 10, ny = 10
  real(dp), parameter :: d = 1.0_dp, x0 = 0.0_dp, y0 = 0.0_dp
  ! The y-lists need only the centres' y.
  real(dp), parameter :: y(n) = [6.45_dp, 6.50_dp, 6.45_dp, 6.80_dp, 6.85_dp, 5.55_dp, 6.60_dp, 5.40_dp, 6.55_dp]
  integer :: y_heads(ny), y_next(n), k, iy

  y_heads = -1
  do k = 1, n
    ! int() truncates toward zero: the row only for centres at or above y0, as all nine are.
    iy = int((y(k) - y0) / d) + 1
#ifdef PLANT_BUG
    if (k == 4) iy = iy - 1  ! element 4 lands one row low: on y_heads(6)'s list, not y_heads(7)'s
#endif
    y_next(k) = y_heads(iy)  ! push k at the head of its row's y-list
    y_heads(iy) = k
  end do
  call write_nbs_ylists(output_unit, nx, d, x0, y0, y_heads, y_next)
end program write_arrays
