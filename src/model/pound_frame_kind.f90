!> The planar frame as a building kind: its nodes, elements, sections, constraints, DOF
!> layout and gravity analysis, described in the listing and written to /model/<b>/.
module pound_frame_kind
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str, fixed_cell
   use pound_model_sink, only: model_sink, text_lines
   use pound_structure, only: structure_model
   use pound_building_kind, only: building_kind
   use pound_frame_building, only: frame_data
   implicit none
   private

   public :: frame_kind

   !> Units of a frame's node map coefficients.
   character(len=*), parameter :: node_coefficient_units = '1 (m where a rotation enters a translation)'
   !> Columns of a frame's node map (`node_dofs`, `node_coefficients`): two terms per direction.
   character(len=*), parameter :: node_map_columns = 'horizontal(term 1, term 2) vertical(term 1, term 2) '// &
                                                     'rotation(term 1, term 2); DOF 0: no term'

   !> A frame's data for the writers.
   type, extends(building_kind) :: frame_kind
      !> Nodes, elements, DOF map, gravity analysis, constraints.
      type(frame_data) :: frame
   contains
      procedure :: describe => frame_describe
      procedure :: write_data => frame_write_data
   end type frame_kind

contains

   !> The frame's geometry, sections, DOFs and (with P-Delta) its gravity analysis.
   subroutine frame_describe(kind, m, lines)
      !> The building kind.
      class(frame_kind), intent(in) :: kind
      !> Its structural model.
      type(structure_model), intent(in) :: m
      !> The lines.
      type(text_lines), intent(inout) :: lines
      character(len=:), allocatable :: cons, text
      character(len=256) :: buf
      integer :: j, e, ln, eb

      associate (f => kind%frame%frame, fd => kind%frame)
         cons = ''
         if (fd%rigid_beams) cons = cons//' rigid_beams'
         if (fd%rigid_diaphragm) cons = cons//' rigid_diaphragm'
         if (fd%rigid_columns) cons = cons//' rigid_columns'
         if (len(cons) == 0) cons = ' none'
         call lines%add('')
         call lines%add('  Building '//m%name//' (frame): '//str(f%n_storeys)//' storeys, '//str(f%n_lines)// &
                        ' column lines, '//str(f%n_nodes)//' nodes, '//str(f%n_elements)//' elements, '// &
                        str(m%n)//' DOFs')
         call lines%add('  half-bandwidth '//str(m%kd)//', constraints:'//cons//', base '//fd%base)
         if (kind%p_delta) then
            call lines%add("  P-Delta on, geometric stiffness '"//fd%geometric// &
                           "' of the gravity analysis (unconstrained frame)")
         else
            call lines%add('  P-Delta off')
         end if
         call lines%add('  x of the column lines [m]:')
         text = '    '
         do j = 1, size(f%line_x)
            text = text//fixed_cell(f%line_x(j), 10, 3)
         end do
         call lines%add(text)
         call lines%add('  storey    h [m]    mass [t]  column E [kN/m2]'// &
                        '   A [m2]     I [m4]  beam E [kN/m2]   A [m2]     I [m4]')
         do j = 1, f%n_storeys
            e = first_element(j, 1)
            eb = first_element(j, 2)
            if (eb == 0) eb = e
            write (buf, '(2x,i6,a9,a12,es18.5,2es11.3,es16.5,2es11.3)') j, &
               fixed_cell(kind%height(j), 9, 3, .true.), fixed_cell(kind%floor_mass(j), 12, 4, .true.), &
               f%element_e(e), f%element_a(e), f%element_i(e), f%element_e(eb), f%element_a(eb), &
               f%element_i(eb)
            call lines%add(trim(buf))
         end do
         if (kind%p_delta) then
            write (buf, '(a,es12.4,a)') '  gravity analysis: total load ', &
               fd%gravity%total_load, ' kN; base reactions per column line (H [kN], V [kN], M [kN m]):'
            call lines%add(trim(buf))
            do ln = 1, f%n_lines
               write (buf, '(4x,i6,3es13.4)') ln, fd%gravity%reactions(:, ln)
               call lines%add(trim(buf))
            end do
            call lines%add('  column axial force N [kN] (tension +) at the '// &
                           'bottom of each storey, column lines 1.. (at most 8):')
            do j = 1, f%n_storeys
               write (buf, '(4x,i6,8es13.4)') j, (fd%gravity%axial(bottom_column(j, ln)), ln=1, min(f%n_lines, 8))
               call lines%add(trim(buf))
            end do
         end if
      end associate

   contains

      !> First element of storey/floor j of kind k (1 column, 2 beam); 0 if none.
      integer function first_element(j, k) result(e)
         integer, intent(in) :: j, k

         do e = 1, kind%frame%frame%n_elements
            if (kind%frame%frame%element_group(e) == j .and. kind%frame%frame%element_kind(e) == k) return
         end do
         e = 0
      end function first_element

      !> The lowest column element of storey j on column line `line`.
      integer function bottom_column(j, line) result(e)
         integer, intent(in) :: j, line

         do e = 1, kind%frame%frame%n_elements
            if (kind%frame%frame%element_kind(e) == 1 .and. kind%frame%frame%element_group(e) == j .and. &
                kind%frame%frame%node_line(kind%frame%frame%element_nodes(1, e)) == line) return
         end do
         e = 1
      end function bottom_column

   end subroutine frame_describe

   !> A frame's nodes (x, z per node), elements (end nodes, kind 1 column / 2 beam, storey
   !> or floor) and sections (E, A, I per element), its gravity analysis, its column
   !> segments, and the DOF layout of its `u_nodes`: node and direction of each DOF, and
   !> each node's displacements as combinations of the DOFs (the constraints' master-slave map).
   subroutine frame_write_data(kind, m, sink, error)
      !> The building kind.
      class(frame_kind), intent(in) :: kind
      !> Its structural model.
      type(structure_model), intent(in) :: m
      !> Where to write.
      class(model_sink), intent(inout) :: sink
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      associate (f => kind%frame%frame)
         call sink%real_table('nodes', reshape([f%node_x, f%node_z], [f%n_nodes, 2]), 'm', 'x z (m)', error)
         if (allocated(error)) return
         call sink%int_table('elements', reshape([f%element_nodes(1, :), f%element_nodes(2, :), &
                             f%element_kind, f%element_group], [f%n_elements, 4]), '1', &
                             'node1 node2 kind(1 column, 2 beam) storey', error)
         if (allocated(error)) return
         call sink%real_table('sections', reshape([f%element_e, f%element_a, f%element_i], &
                              [f%n_elements, 3]), 'kN/m^2, m^2, m^4', 'E (kN/m2) A (m2) I (m4)', error)
         if (allocated(error)) return
         if (kind%p_delta) call sink%reals('gravity_axial_force', kind%frame%gravity%axial, 'kN', error)
         if (allocated(error)) return
         associate (ce => kind%frame%column_element)
            call sink%int_table('columns', reshape([ce, f%element_group(ce), f%node_line(f%element_nodes(1, ce))], &
                                [size(ce), 3]), '1', 'element storey line of each column '// &
                                'segment of /<analysis>/<b>/columns and /influence/<b>/columns '// &
                                '(element: row of elements, 1-based)', error)
         end associate
         if (allocated(error)) return
         call sink%int_table('dofs', reshape([m%dof_node, m%dof_direction], [m%n, 2]), '1', &
                             'node direction(1 horizontal, 2 vertical, 3 rotation)', error)
         if (allocated(error)) return
         call sink%int_table('node_dofs', transpose(reshape(f%map_dof, [6, f%n_nodes])), '1', node_map_columns, error)
         if (allocated(error)) return
         call sink%real_table('node_coefficients', transpose(reshape(f%map_coef, [6, f%n_nodes])), &
                              node_coefficient_units, node_map_columns, error)
      end associate
   end subroutine frame_write_data

end module pound_frame_kind
