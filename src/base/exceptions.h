// SPDX-License-Identifier: LGPL-2.1-or-later
// Exception types of wearlink. Three kinds of failure reach the user:
//  - InputError: the scene, a file or a command line is wrong; the message says what is
//    wrong, where (file and entry path), what is allowed and how to fix it.
//  - NumericalError: a valid scene that the numerics could not handle (assembly Newton
//    did not converge, step size underflow, contact solver cycling); the message carries
//    time, joint, iteration and residual.
//  - EstimationError: a series does not allow the estimate asked of it (too short for the
//    embedding, constant, no neighbour beyond the Theiler window). Where the series came
//    from the user, the caller turns it into an InputError naming the file or the scene
//    entry; where a comparison asked, the missing value is reported with this reason.
//  - IoError: the environment failed a valid request: an output file or directory that
//    cannot be created or written (permission, disk full, a rename that fails). Exit 4.
//  - Interrupted: SIGINT or SIGTERM arrived (base/interrupt.h); the program removes its
//    temporary files on the way out and exits with 128 + the signal's number.
// Exit status 1 is left for internal errors (our own bugs); src/app/main.cc maps the
// types to the codes and doc/running.md ("Exit status") lists them.
// Our own bugs are caught by deal.II's Assert (debug builds only).
#pragma once

#include <deal.II/base/exceptions.h>

#include <string>
#include <utility>

namespace wearlink
{
  /** Base of wearlink's user-facing exceptions: the message is all there is to print. */
  class Error : public dealii::ExceptionBase
  {
  public:
    explicit Error(std::string message);

    /** The message for the user (no stack trace, no source location). */
    const std::string &
    message() const
    {
      return text;
    }

    void
    print_info(std::ostream &out) const override;

    const char *
    what() const noexcept override
    {
      return text.c_str();
    }

  private:
    std::string text;
  };

  /** The user's input (scene, file, command line) is wrong. Exit status 2. */
  class InputError : public Error
  {
  public:
    using Error::Error;
  };

  /** A series that does not allow the estimate asked of it (see above). Exit status 2. */
  class EstimationError : public Error
  {
  public:
    using Error::Error;
  };

  /** A valid scene the numerics could not carry through. Exit status 3. */
  class NumericalError : public Error
  {
  public:
    using Error::Error;
  };

  /** The environment failed a valid request (cannot write a file, disk full). Exit status 4. */
  class IoError : public Error
  {
  public:
    using Error::Error;
  };

  /** The run was stopped by a signal (SIGINT, SIGTERM). Exit status 128 + signal. */
  class Interrupted : public Error
  {
  public:
    Interrupted(std::string message, const int signal_number)
      : Error(std::move(message))
      , number(signal_number)
    {
    }

    int
    signal_number() const
    {
      return number;
    }

  private:
    int number;
  };
} // namespace wearlink
